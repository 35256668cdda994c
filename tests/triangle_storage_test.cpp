// What a scene's TriangleSoA stores: v0, the edges and the material always; the scaled normal
// only for Moller-Trumbore and the other two vertices only for the watertight test; the unit
// normal never (computed from the edges). A scene built for one test and then asked to run the
// other is refused with a message, never read out of bounds.

#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/scene/scene.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/renderer.h"
#include "bvh_test_scenes.h"

namespace wt {
namespace {

// The hexroom with its meshes, every quad split into two triangles, so that a scene built for
// Moller-Trumbore has no parallelogram (which alone would make the watertight test refuse it).
SceneDescription hexroom_of_triangles(TriangleTest test) {
    SceneDescription d = test::hexroom_with_meshes(4, 4, 1);
    for (TriangleMesh& m : d.meshes) m.parallelogram = false;
    d.settings.accuracy.triangles = test;
    return d;
}

TEST(TriangleStorage, ASceneStoresOnlyTheRowsItsTestReads) {
    const Scene mt = build_scene(hexroom_of_triangles(TriangleTest::moller_trumbore));
    const Scene wt = build_scene(hexroom_of_triangles(TriangleTest::watertight));
    ASSERT_GT(mt.triangles.size(), 2000u);
    ASSERT_EQ(wt.triangles.size(), mt.triangles.size());
    const std::size_t n = mt.triangles.size();

    EXPECT_TRUE(mt.triangles.has_scaled_normal());
    EXPECT_FALSE(mt.triangles.has_vertices());
    EXPECT_EQ(mt.triangles.scaled_nx.size(), n);
    EXPECT_TRUE(mt.triangles.v1x.empty() && mt.triangles.v2z.empty());
    EXPECT_EQ(mt.triangles.bytes(), n * (12 * sizeof(float) + sizeof(uint32_t)));  // 52 B

    EXPECT_TRUE(wt.triangles.has_vertices());
    EXPECT_FALSE(wt.triangles.has_scaled_normal());
    EXPECT_EQ(wt.triangles.v1x.size(), n);
    EXPECT_TRUE(wt.triangles.scaled_nx.empty());
    EXPECT_EQ(wt.triangles.bytes(), n * (15 * sizeof(float) + sizeof(uint32_t)));  // 64 B

    // A TriangleSoA of its own (tests, benchmarks) keeps both, for either test.
    TriangleSoA both;
    both.push_back({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0);
    EXPECT_TRUE(both.serves(TriangleTest::moller_trumbore) && both.serves(TriangleTest::watertight));
    EXPECT_FALSE(mt.triangles.serves(TriangleTest::watertight));
    EXPECT_FALSE(wt.triangles.serves(TriangleTest::moller_trumbore));
    EXPECT_THROW(both.store_only_for(TriangleTest::watertight), std::logic_error);
}

TEST(TriangleStorage, NormalsAndVerticesAreWhatTheTestSees) {
    const SceneDescription d = hexroom_of_triangles(TriangleTest::moller_trumbore);
    const Scene mt = build_scene(d);
    const Scene wt = build_scene(hexroom_of_triangles(TriangleTest::watertight));
    std::size_t i = 0, slivers = 0;
    for (const TriangleMesh& m : d.meshes)
        for (const auto& tri : m.triangles) {
            const glm::vec3 a = m.vertices[tri[0]], b = m.vertices[tri[1]], c = m.vertices[tri[2]];
            SCOPED_TRACE("triangle " + std::to_string(i));
            ASSERT_EQ(mt.triangles.vertex0(i), wt.triangles.vertex0(i));
            const glm::vec3 n = mt.triangles.normal(i);
            if (is_sliver(a, b, c)) {
                EXPECT_EQ(n, glm::vec3(0.0f));  // stored collapsed: no direction
                ++slivers;
            } else {
                // The unit normal of the given corners, to the rounding of the edges.
                const glm::vec3 expected = glm::normalize(glm::cross(b - a, c - a));
                EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
                EXPECT_GT(glm::dot(n, expected), 1.0f - 1e-5f);
                // The watertight scene keeps the corners as given; Moller-Trumbore's are v0 + e.
                EXPECT_EQ(wt.triangles.vertex1(i), b);
                EXPECT_EQ(wt.triangles.vertex2(i), c);
                EXPECT_EQ(mt.triangles.vertex1(i), mt.triangles.vertex0(i) + mt.triangles.edge1(i));
                EXPECT_EQ(mt.triangles.vertex2(i), mt.triangles.vertex0(i) + mt.triangles.edge2(i));
            }
            EXPECT_EQ(wt.triangles.normal(i), n);  // the same edges, the same bits
            ++i;
        }
    EXPECT_EQ(i, mt.triangles.size());
    EXPECT_LT(slivers, i / 100);
}

TEST(TriangleStorage, TheOtherTestIsRefusedNotReadOutOfBounds) {
    for (TriangleTest built : {TriangleTest::moller_trumbore, TriangleTest::watertight}) {
        SCOPED_TRACE(std::string("built for ") + name_of(built));
        Scene scene = build_scene(hexroom_of_triangles(built));
        ASSERT_EQ(scene.triangles.parallelogram_count, 0u);
        EXPECT_NO_THROW(scene_view(scene));
        scene.settings.accuracy.triangles =
            built == TriangleTest::moller_trumbore ? TriangleTest::watertight : TriangleTest::moller_trumbore;
        try {
            Film film(4, 4);
            render(scene, RenderOptions{}, film);
            ADD_FAILURE() << "render accepted triangles stored for another test";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("stored for another triangle test"), std::string::npos) << e.what();
        }
        EXPECT_THROW(scene_view(scene), std::invalid_argument);
    }
}

// The copy a BVH keeps of a scene's parallelograms (tested beside its tree): the first n entries
// of exactly the rows the scene stores, bit for bit, and its parallelograms among them.
TEST(TriangleStorage, FirstCopiesTheLeadingEntriesOfTheStoredRows) {
    const Scene scene = build_scene(test::hexroom_with_meshes(4, 4, 1));
    const TriangleSoA& t = scene.triangles;
    ASSERT_GT(t.parallelogram_count, 0u);
    ASSERT_GT(t.size(), std::size_t(t.parallelogram_count) + 2);
    for (const std::size_t n : {std::size_t(t.parallelogram_count), std::size_t(t.parallelogram_count) + 2}) {
        const TriangleSoA first = t.first(n);
        ASSERT_EQ(first.size(), n);
        EXPECT_EQ(first.parallelogram_count, t.parallelogram_count);
        EXPECT_EQ(first.has_scaled_normal(), t.has_scaled_normal());
        EXPECT_EQ(first.has_vertices(), t.has_vertices());
        EXPECT_TRUE(first.v1x.empty());
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_EQ(first.vertex0(i), t.vertex0(i)) << i;
            EXPECT_EQ(first.edge1(i), t.edge1(i)) << i;
            EXPECT_EQ(first.edge2(i), t.edge2(i)) << i;
            EXPECT_EQ(first.scaled_normal(i), t.scaled_normal(i)) << i;
            EXPECT_EQ(first.material[i], t.material[i]) << i;
        }
    }
    EXPECT_EQ(t.first(1).parallelogram_count, 1u);
    EXPECT_THROW(t.first(t.size() + 1), std::logic_error);
}

}  // namespace
}  // namespace wt
