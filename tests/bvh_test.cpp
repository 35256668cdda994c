// The BVH against the flat kernels it replaces, and the tree's own invariants. The traversal
// must return the flat list's bits for every ray (same primitive, t, u and v; same occlusion
// answer): it runs the same primitive tests and breaks ties on equal t by primitive id as the
// flat loop's order does, so there is no "either of two" to allow, even on shared edges.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "bvh_test_scenes.h"
#include "core/system/thread_pool.h"
#include "kernels/accel/bvh.h"
#include "kernels/accel/sah_builder.h"
#include "kernels/isa/intersect_dispatch.h"
#include "sanitizer_scale.h"
#include "test_scenes.h"

namespace wt {
namespace {

#ifndef WT_LONG_TESTS
#define WT_LONG_TESTS 0
#endif
constexpr int kRandomRays = test::sanitizer_scaled(WT_LONG_TESTS ? 1 << 21 : 1 << 16);

// What the flat kernels answer for a ray set: the reference every BVH build is held to. The
// flat kernels equal the scalar textbook on every ISA (packet_intersect_test), so the widest
// one this CPU runs stands for all of them.
struct FlatAnswers {
    test::HitArrays closest[2]{test::HitArrays(0), test::HitArrays(0)};  // unbounded, bounded
    std::vector<uint8_t> any[2];

    FlatAnswers(const Scene& scene, const test::RayBatch& rays) {
        const IntersectKernels& k = intersect_kernels(best_supported_isa(), scene.settings.accuracy);
        const FlatScene flat(scene);
        for (int bounded = 0; bounded < 2; ++bounded) {
            closest[bounded] = test::HitArrays(rays.size());
            any[bounded].assign(rays.size(), 7);
            k.closest_raypacket(flat.view(), rays.view(bounded), closest[bounded].view());
            k.any_raypacket(flat.view(), rays.view(bounded), any[bounded].data());
        }
    }
};

// Both BVH traversals, one ray at a time and packets of the ISA's width, against the flat answers.
void expect_bvh_matches_flat(const Scene& scene, const test::RayBatch& rays, const FlatAnswers& flat, Isa isa,
                             const BvhBuildOptions& options, const std::string& what) {
    SCOPED_TRACE(what + ", isa " + isa_name(isa) + ", width " + std::to_string(options.node_width) + ", leaf " +
                 std::to_string(options.max_leaf_size) + (options.parallelograms_beside ? "" : ", parallelograms in the tree"));
    const Bvh bvh = build_bvh(scene, options);
    const IntersectKernels& k = intersect_kernels(isa, scene.settings.accuracy);
    const BvhView tree = bvh_view(bvh);
    // The walks a tree past kBvhPrefetchBytes gets (several rays' walks interleaved, the
    // occlusion walks prefetching what they push), on this small one.
    BvhView interleaved = tree;
    interleaved.prefetch_pushed = true;
    const std::size_t n = rays.size();
    struct Traversal {
        const char* name;
        decltype(k.closest_bvh) closest;
        decltype(k.any_bvh) any;
        const BvhView& tree;
    };
    for (const Traversal& traversal : {Traversal{"single rays", k.closest_bvh, k.any_bvh, tree},
                                       Traversal{"interleaved walks", k.closest_bvh, k.any_bvh, interleaved},
                                       Traversal{"packets", k.closest_bvh_packets, k.any_bvh_packets, tree}}) {
        SCOPED_TRACE(traversal.name);
        for (int bounded = 0; bounded < 2; ++bounded) {
            if (traversal.closest) {
                const test::HitArrays& expected = flat.closest[bounded];
                test::HitArrays got(n);
                traversal.closest(traversal.tree, rays.view(bounded), got.view());
                std::size_t mismatches = 0, first_bad = n;
                for (std::size_t i = 0; i < n; ++i) {
                    const bool same = expected.prim[i] == got.prim[i] && expected.t[i] == got.t[i] &&
                                      (expected.prim[i] == kNoHit || (expected.u[i] == got.u[i] && expected.v[i] == got.v[i]));
                    if (!same && mismatches++ == 0) first_bad = i;
                }
                EXPECT_EQ(mismatches, 0u) << "closest, bounded " << bounded << ": first at ray " << first_bad << " (flat prim "
                                          << (first_bad < n ? expected.prim[first_bad] : 0) << " t "
                                          << (first_bad < n ? expected.t[first_bad] : 0) << ", bvh prim "
                                          << (first_bad < n ? got.prim[first_bad] : 0) << " t "
                                          << (first_bad < n ? got.t[first_bad] : 0) << ")";
            }
            std::vector<uint8_t> occluded(n, 9);
            traversal.any(traversal.tree, rays.view(bounded), occluded.data());
            std::size_t any_mismatches = 0;
            for (std::size_t i = 0; i < n; ++i) any_mismatches += flat.any[bounded][i] != occluded[i];
            EXPECT_EQ(any_mismatches, 0u) << "any, bounded " << bounded;
        }
    }
}

std::vector<Isa> supported_isas() {
    std::vector<Isa> isas;
    for (Isa isa : kAllIsas)
        if (cpu_supports(isa)) isas.push_back(isa);
    return isas;
}

// Every width and leaf size with the hexroom's parallelograms beside the tree (the default),
// and one with them in it.
std::vector<BvhBuildOptions> build_variants() {
    std::vector<BvhBuildOptions> all;
    for (int width : {4, 8})
        for (int leaf : {1, 4, 8}) all.push_back({width, leaf, 2});
    all.push_back({8, 8, 2, false});
    return all;
}

TEST(Bvh, HexroomEqualsFlatKernelsOnEveryIsaWidthLeafSizeAndAccuracy) {
    for (const AccuracySettings& accuracy : test::accuracy_variants()) {
        SceneDescription d = test::hexroom(8, 8, 1);
        d.settings.accuracy = accuracy;
        const Scene scene = build_scene(d);
        const test::RayBatch rays = test::scene_rays(scene, kRandomRays, 11);
        const FlatAnswers flat(scene, rays);
        for (Isa isa : supported_isas())
            for (const BvhBuildOptions& o : build_variants())
                expect_bvh_matches_flat(scene, rays, flat, isa, o, std::string("hexroom, ") + name_of(accuracy.triangles));
    }
}

TEST(Bvh, MeshSceneEqualsFlatKernels) {
    // The hexroom with a 2,000-triangle displaced sphere and a closed icosphere: shared edges,
    // vertices and thin triangles at every angle.
    for (TriangleTest test : {TriangleTest::moller_trumbore, TriangleTest::watertight}) {
        SceneDescription d = test::hexroom_with_meshes(8, 8, 1);
        d.settings.accuracy.triangles = test;
        const Scene scene = build_scene(d);
        const test::RayBatch rays = test::scene_rays(scene, kRandomRays, 12);
        const FlatAnswers flat(scene, rays);
        for (Isa isa : supported_isas())
            for (int width : {4, 8}) expect_bvh_matches_flat(scene, rays, flat, isa, {width, 8, 2}, std::string("meshes, ") + name_of(test));
    }
}

// Shadow rays as a tile sends them: neighbours in the queue start at neighbouring points and
// go to one light, in runs the meshes block and runs they do not. The random rays of the tests
// above rarely come in such runs, which are what a traversal that carries anything from one
// ray to the next (an occluder cache, packets of shadow rays) must answer as the flat list does.
TEST(Bvh, CoherentShadowRaysEqualFlatKernels) {
    const Scene scene = build_scene(test::hexroom_with_meshes(8, 8, 1));
    const TriangleSoA& t = scene.triangles;
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    for (std::size_t i = t.parallelogram_count; i < t.size(); ++i)  // the meshes' small triangles, not the room's floor
        if (glm::length(t.edge1(i)) < 1.0f && glm::length(t.edge2(i)) < 1.0f)
            for (const glm::vec3& v : {t.vertex0(i), t.vertex1(i), t.vertex2(i)}) lo = glm::min(lo, v), hi = glm::max(hi, v);
    ASSERT_TRUE(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z);
    const glm::vec3 extent = hi - lo;
    // The meshes stand on the hexroom's floor (z = -5) under its ceiling (z = 5): the rays start
    // just above the floor, around and under them, toward a point light below the ceiling.
    const float floor_z = -4.9f;
    const glm::vec3 light(0.5f * (lo.x + hi.x), 0.5f * (lo.y + hi.y), 4.5f);
    constexpr int kSide = 96;
    test::RayBatch rays;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const glm::vec3 origin(lo.x - 0.5f * extent.x + 2.0f * extent.x * (float(x) + 0.5f) / kSide,
                                   lo.y - 0.5f * extent.y + 2.0f * extent.y * (float(y) + 0.5f) / kSide, floor_z);
            const glm::vec3 to_light = light - origin;
            const float distance = glm::length(to_light);
            rays.push({origin, to_light / distance}, distance * 0.999f);
        }
    const FlatAnswers flat(scene, rays);
    const std::size_t blocked = std::size_t(std::count(flat.any[1].begin(), flat.any[1].end(), uint8_t(1)));
    EXPECT_GT(blocked, rays.size() / 10) << "the meshes must block a run of rays";
    EXPECT_LT(blocked, rays.size() * 9 / 10) << "and leave runs unblocked";
    for (Isa isa : supported_isas())
        for (const BvhBuildOptions& o : build_variants()) expect_bvh_matches_flat(scene, rays, flat, isa, o, "coherent shadow rays");
}

// The interleaved walks (bvh_interleaved_traverse.h) start, retire and refill kInterleavedWalks
// rays at a time: a queue shorter than that, one just past it, and the tail of a longer one
// must each get every ray's answer, and write nothing past the queue's end.
TEST(Bvh, InterleavedWalksAnswerQueuesOfEveryLength) {
    const Scene scene = build_scene(test::hexroom_with_meshes(8, 8, 1));
    const test::RayBatch rays = test::scene_rays(scene, 64, 13);
    const FlatAnswers flat(scene, rays);
    for (Isa isa : supported_isas()) {
        const IntersectKernels& k = intersect_kernels(isa, scene.settings.accuracy);
        const Bvh bvh = build_bvh(scene, {8, 8, 2});
        BvhView interleaved = bvh_view(bvh);
        interleaved.prefetch_pushed = true;
        for (std::size_t first : {std::size_t(0), std::size_t(5)})
            for (std::size_t count = 0; count <= 19; ++count) {
                SCOPED_TRACE(std::string("isa ") + isa_name(isa) + ", rays " + std::to_string(first) + " + " + std::to_string(count));
                test::HitArrays got(count + 1);
                got.prim[count] = 12345;  // one past the queue: left alone
                k.closest_bvh(interleaved, rays.view(true, first, count), got.view());
                std::vector<uint8_t> occluded(count + 1, 9);
                k.any_bvh(interleaved, rays.view(true, first, count), occluded.data());
                for (std::size_t i = 0; i < count; ++i) {
                    EXPECT_EQ(got.prim[i], flat.closest[1].prim[first + i]) << "ray " << i;
                    EXPECT_EQ(got.t[i], flat.closest[1].t[first + i]) << "ray " << i;
                    EXPECT_EQ(occluded[i], flat.any[1][first + i]) << "ray " << i;
                }
                EXPECT_EQ(got.prim[count], 12345u);
                EXPECT_EQ(occluded[count], 9);
            }
    }
}

TEST(Bvh, AxisAlignedRaysWithZeroDirectionComponents) {
    const Scene scene = build_scene(test::hexroom_with_meshes(8, 8, 1));
    test::RayBatch rays;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> ux(-2.5f, 12.5f), uy(-5.5f, 5.5f), uz(-4.9f, 4.9f);
    const glm::vec3 axes[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {-0.0f, 0.0f, 1.0f}};
    // Few: incoherent packets with infinite slab distances visit most of the tree.
    for (int i = 0; i < test::sanitizer_scaled(3000); ++i) {
        const glm::vec3 o(ux(rng), uy(rng), uz(rng));
        for (const glm::vec3& a : axes) rays.push({o, a}, 30.0f);
    }
    // Origins exactly on box planes: the vertices themselves, axis-aligned directions.
    const TriangleSoA& t = scene.triangles;
    for (uint32_t i = 0; i < t.size(); i += 7 * test::kSanitizerRayDivisor)
        for (const glm::vec3& a : axes) rays.push({t.vertex0(i) - 3.0f * a, a}, 30.0f);
    const FlatAnswers flat(scene, rays);
    for (Isa isa : supported_isas())
        for (int width : {4, 8}) expect_bvh_matches_flat(scene, rays, flat, isa, {width, 8, 2}, "axis-aligned");
}

TEST(Bvh, DegenerateSets) {
    struct Case {
        const char* name;
        SceneDescription scene;
    };
    std::vector<Case> cases;
    cases.push_back({"one triangle", test::triangle_soup(1, 1.0f, glm::vec3(0.0f), 1)});
    cases.push_back({"same centroid", test::same_centroid_fan(300)});
    cases.push_back({"coplanar", test::coplanar_grid(40)});
    cases.push_back({"tiny scale", test::triangle_soup(3000, 1e-6f, glm::vec3(0.0f), 2)});
    cases.push_back({"huge scale", test::triangle_soup(3000, 1e6f, glm::vec3(0.0f), 3)});
    cases.push_back({"far from origin", test::triangle_soup(3000, 1.0f, glm::vec3(1e5f, -1e5f, 1e5f), 4)});
    for (const Case& c : cases) {
        const Scene scene = build_scene(c.scene);
        const test::RayBatch rays = test::rays_at_primitives(scene, test::sanitizer_scaled(20000), 21);
        const FlatAnswers flat(scene, rays);
        for (Isa isa : supported_isas())
            for (int width : {4, 8}) expect_bvh_matches_flat(scene, rays, flat, isa, {width, 8, 2}, c.name);
    }
}

TEST(Bvh, EmptySceneHitsNothing) {
    SceneDescription d = test::triangle_soup(1, 1.0f, glm::vec3(0.0f), 1);
    d.meshes.clear();
    const Scene scene = build_scene(d);
    const Bvh bvh = build_bvh(scene);
    test::RayBatch rays;
    rays.push({{0, 0, 0}, {1, 0, 0}});
    for (Isa isa : supported_isas()) {
        test::HitArrays hits(1);
        std::vector<uint8_t> occluded(1, 7);
        intersect_kernels(isa).closest_bvh(bvh_view(bvh), rays.view(false), hits.view());
        intersect_kernels(isa).any_bvh(bvh_view(bvh), rays.view(false), occluded.data());
        EXPECT_EQ(hits.prim[0], kNoHit);
        EXPECT_EQ(occluded[0], 0);
    }
}

// Every primitive in exactly one leaf (but the parallelograms tested beside the tree), every box
// inside its parent's, the same tree for any thread count.
TEST(Bvh, BuildInvariantsAndDeterminism) {
    const Scene scene = build_scene(test::hexroom_with_meshes(8, 8, 1));
    ASSERT_GT(scene.triangles.parallelogram_count, 0u);
    ASSERT_LE(scene.triangles.parallelogram_count, kBvhMostBeside);
    ASSERT_GT(scene.spheres.size(), 0u) << "sphere leaves, whose blocks use only their first rows";
    for (const bool beside : {true, false})
    for (int width : {4, 8}) {
        SCOPED_TRACE(beside ? "parallelograms beside the tree" : "parallelograms in the tree");
        const Bvh one = build_bvh(scene, {width, 8, 1, beside});
        EXPECT_EQ(one.stats().beside_count, beside ? scene.triangles.parallelogram_count : 0u);
        const test::BvhDump reference = test::dump_bvh(bvh_view(one));
        EXPECT_TRUE(reference.parents_contain_children) << "width " << width;
        std::vector<uint32_t> ids = reference.primitive_ids;
        std::sort(ids.begin(), ids.end());
        std::vector<uint32_t> expected;
        for (uint32_t i = uint32_t(one.stats().beside_count); i < scene.primitive_count(); ++i)
            if (i >= scene.triangles.size() || !(scene.triangles.edge1(i) == glm::vec3(0.0f) && scene.triangles.edge2(i) == glm::vec3(0.0f)))
                expected.push_back(i);
        EXPECT_EQ(ids, expected) << "every primitive exactly once, width " << width;
        EXPECT_LE(reference.max_leaf_size, 8u);
        EXPECT_TRUE(reference.leaves_one_kind);
        // The blocks are allocated without zeroing (their pages first touched by the threads
        // that fill them): every float must be written, the unused rows of a sphere leaf too.
        EXPECT_TRUE(reference.sphere_rows_past_id_zero);
        for (int threads : {2, 3}) {
            const test::BvhDump other = test::dump_bvh(bvh_view(build_bvh(scene, {width, 8, threads, beside})));
            EXPECT_TRUE(other == reference) << "tree differs with " << threads << " threads, width " << width;
        }
        EXPECT_GT(one.stats().sah_cost, 0.0);
        EXPECT_EQ(one.stats().leaf_count, reference.leaf_count);
    }
}

TEST(Bvh, RejectsBadOptions) {
    const Scene scene = build_scene(test::hexroom(8, 8, 1));
    EXPECT_THROW(build_bvh(scene, {2, 8, 1}), std::invalid_argument);
    EXPECT_THROW(build_bvh(scene, {8, 0, 1}), std::invalid_argument);
    EXPECT_THROW(build_bvh(scene, {8, 9, 1}), std::invalid_argument);
}

// A reference keeps its id, kind and bins in the fourth lanes of its corners. Read as floats
// those are mostly denormals, and arithmetic on them took microcode assists that were most of
// the build's time: its box and centroid must be those of its corners alone, lane 3 zero.
TEST(SahBuilder, ReferenceBoxAndCentroidIgnoreTheIdKindAndBinsBesideTheCorners) {
    auto lanes = [](__m128 v) {
        std::array<uint32_t, 4> bits;
        std::memcpy(bits.data(), &v, sizeof v);
        return bits;
    };
    PrimRef plain{}, tagged{};
    for (PrimRef* r : {&plain, &tagged}) {
        r->lo[0] = -1.0f, r->lo[1] = 2.0f, r->lo[2] = 0.5f;
        r->hi[0] = 3.0f, r->hi[1] = 2.5f, r->hi[2] = 4.0f;
    }
    tagged.id = 12345;  // a denormal as a float
    tagged.kind = uint8_t(BvhLeafKind::sphere);
    tagged.bin[0] = 31, tagged.bin[1] = 7, tagged.bin[2] = 200;
    EXPECT_EQ(lanes(tagged.box().lo), lanes(plain.box().lo));
    EXPECT_EQ(lanes(tagged.box().hi), lanes(plain.box().hi));
    EXPECT_EQ(lanes(tagged.centroid_times_two()), lanes(plain.centroid_times_two()));
    EXPECT_EQ(lanes(tagged.box().lo)[3], 0u);
    EXPECT_EQ(lanes(tagged.box().hi)[3], 0u);
    EXPECT_EQ(lanes(tagged.centroid_times_two())[3], 0u);
    EXPECT_EQ(lanes(tagged.centroid_times_two())[0], lanes(_mm_set1_ps(2.0f))[0]);  // -1 + 3
}

TEST(SahBuilder, LeafBlockMustBeAPowerOfTwo) {
    ThreadPool pool(1);
    for (uint32_t block : {0u, 3u, 6u}) {
        PrimRefs refs(4);
        SahSettings settings;
        settings.leaf_block = block;
        EXPECT_THROW(build_binary_sah(refs, settings, pool), std::invalid_argument) << "leaf block " << block;
    }
    for (uint32_t block : {1u, 8u}) {
        PrimRefs refs(2);
        for (uint32_t i = 0; i < 2; ++i) {
            const float x = float(i);
            refs[i] = PrimRef{{x, 0.0f, 0.0f}, i, {x + 0.5f, 1.0f, 1.0f}, uint8_t(BvhLeafKind::triangle), {0, 0, 0}};
        }
        SahSettings settings;
        settings.leaf_block = block;
        const BinaryTree tree = build_binary_sah(refs, settings, pool);
        EXPECT_TRUE(tree.nodes[tree.root].is_leaf()) << "two triangles under the leaf size make one leaf, leaf block " << block;
    }
}

}  // namespace
}  // namespace wt
