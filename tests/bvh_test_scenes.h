#pragma once
// Scenes, ray sets and a tree walker for the BVH tests: meshes with many shared edges, the
// degenerate sets a builder must survive, and rays aimed where traversal bugs hide (vertices,
// edges, surface planes, rays leaving surfaces, axis-aligned directions).

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "core/base/ray_offset.h"
#include "core/scene/scene.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/primitives/soa_views.h"
#include "kernel_test_helpers.h"
#include "test_scenes.h"

namespace wt::test {

struct HitArrays {
    std::vector<float> t, u, v;
    std::vector<uint32_t> prim;
    explicit HitArrays(std::size_t n) : t(n, -1.0f), u(n), v(n), prim(n, 12345) {}
    HitView view() { return {t.data(), u.data(), v.data(), prim.data()}; }
};

inline glm::vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<float> n;
    for (;;) {
        const glm::vec3 d(n(rng), n(rng), n(rng));
        if (glm::length(d) > 1e-3f) return glm::normalize(d);
    }
}

// test::icosphere displaced radially by up to `bump` of its radius: still closed, with shared
// edges at every angle.
inline TriangleMesh bumpy_icosphere(const glm::vec3& center, float radius, int levels, float bump) {
    TriangleMesh m = icosphere(levels);
    for (glm::vec3& x : m.vertices) {
        const float d = 1.0f + bump * std::sin(7.0f * x.x) * std::sin(5.0f * x.y + 1.0f) * std::cos(3.0f * x.z);
        x = center + radius * d * x;
    }
    return m;
}

// The hexroom plus a bumpy 5,120-triangle icosphere and a small 320-triangle one touching the floor.
inline SceneDescription hexroom_with_meshes(int width, int height, int spp) {
    SceneDescription d = hexroom(width, height, spp);
    d.meshes.push_back(bumpy_icosphere({5.0f, 0.5f, 1.0f}, 1.8f, 4, 0.08f));
    d.meshes.push_back(icosphere(2, 0.8f, {8.0f, 3.0f, -4.2f}));
    return d;
}

inline SceneDescription single_material_scene() {
    SceneDescription d;
    Material m;
    m.name = "white";
    m.albedo = glm::vec3(0.5f);
    d.materials.push_back(m);
    d.camera.eye = glm::vec3(-5.0f, 0.0f, 0.0f);
    d.camera.look_at = glm::vec3(0.0f);
    return d;
}

// `count` random triangles of size ~scale inside a cube of side 10 * scale around `center`.
inline SceneDescription triangle_soup(int count, float scale, const glm::vec3& center, uint32_t seed) {
    SceneDescription d = single_material_scene();
    d.camera.eye = center - glm::vec3(20.0f * scale, 0.0f, 0.0f);
    d.camera.look_at = center;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-5.0f, 5.0f);
    TriangleMesh m;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 c = center + scale * glm::vec3(u(rng), u(rng), u(rng));
        for (int k = 0; k < 3; ++k) m.vertices.push_back(c + scale * 0.3f * random_unit(rng));
        m.triangles.push_back({uint32_t(3 * i), uint32_t(3 * i + 1), uint32_t(3 * i + 2)});
    }
    d.meshes.push_back(m);
    return d;
}

// Triangles all sharing one centroid (a fan of rotated copies): no split by centroid exists.
inline SceneDescription same_centroid_fan(int count) {
    SceneDescription d = single_material_scene();
    TriangleMesh m;
    for (int i = 0; i < count; ++i) {
        const float a = 6.2831853f * float(i) / float(count);
        const glm::vec3 e1(std::cos(a), std::sin(a), 0.3f), e2(-std::sin(a), std::cos(a), -0.2f);
        // Centroid (p0 + p1 + p2) / 3 = 0 with p2 = -(p0 + p1).
        m.vertices.push_back(e1), m.vertices.push_back(e2), m.vertices.push_back(-(e1 + e2));
        m.triangles.push_back({uint32_t(3 * i), uint32_t(3 * i + 1), uint32_t(3 * i + 2)});
    }
    d.meshes.push_back(m);
    return d;
}

// An n x n grid of quads as triangle pairs in the plane z = 0: every box is flat.
inline SceneDescription coplanar_grid(int n) {
    SceneDescription d = single_material_scene();
    TriangleMesh m;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) m.vertices.push_back({float(x) - 0.5f * float(n), float(y) - 0.5f * float(n), 0.0f});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const uint32_t a = uint32_t(y * (n + 1) + x), b = a + 1, c = a + uint32_t(n) + 2, e = a + uint32_t(n) + 1;
            m.triangles.push_back({a, b, c}), m.triangles.push_back({a, c, e});
        }
    d.meshes.push_back(m);
    return d;
}

inline void scene_bounds(const Scene& scene, glm::vec3& lo, glm::vec3& hi) {
    lo = glm::vec3(std::numeric_limits<float>::infinity());
    hi = -lo;
    for (uint32_t i = 0; i < scene.triangles.size(); ++i)
        for (const glm::vec3& p : {scene.triangles.vertex0(i), scene.triangles.vertex1(i), scene.triangles.vertex2(i)})
            lo = glm::min(lo, p), hi = glm::max(hi, p);
    for (uint32_t i = 0; i < scene.spheres.size(); ++i) {
        lo = glm::min(lo, scene.spheres.center(i) - scene.spheres.radius[i]);
        hi = glm::max(hi, scene.spheres.center(i) + scene.spheres.radius[i]);
    }
}

// Rays aimed at vertices and edge midpoints from random origins in (and just around) the scene,
// rays in primitives' planes, and rays leaving surfaces from offset points; tmax random, or
// the distance to the target point, as a shadow ray's is.
inline RayBatch rays_at_primitives(const Scene& scene, int count, uint32_t seed) {
    std::mt19937 rng(seed);
    glm::vec3 lo, hi;
    scene_bounds(scene, lo, hi);
    const glm::vec3 size = hi - lo;
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::uniform_int_distribution<uint32_t> pick(0, uint32_t(scene.triangles.size() - 1));
    auto random_origin = [&] { return lo - 0.1f * size + 1.2f * size * glm::vec3(u01(rng), u01(rng), u01(rng)); };
    RayBatch b;
    const TriangleSoA& t = scene.triangles;
    for (int i = 0; i < count && t.size() > 0; ++i) {
        const uint32_t k = pick(rng);
        const glm::vec3 v0 = t.vertex0(k), v1 = v0 + t.edge1(k), v2 = v0 + t.edge2(k);
        const glm::vec3 targets[] = {v0, v1, v2, 0.5f * (v0 + v1), 0.5f * (v1 + v2), 0.5f * (v0 + v2)};
        const glm::vec3 target = targets[i % 6];
        const glm::vec3 o = random_origin();
        const float dist = glm::length(target - o);
        if (!(dist > 0.0f)) continue;
        switch (i % 4) {
            case 0: b.push({o, (target - o) / dist}, 2.0f * dist); break;
            case 1: b.push({o, (target - o) / dist}, dist); break;  // ends at the target
            case 2: {  // in the primitive's plane, through its centroid
                const glm::vec3 centroid = (v0 + v1 + v2) / 3.0f;
                if (glm::length(t.edge1(k)) > 0.0f) b.push({centroid - t.edge1(k), glm::normalize(t.edge1(k))}, 4.0f * glm::length(size));
                break;
            }
            default: {  // leaving the surface from its centroid, either side
                const glm::vec3 n = (u01(rng) < 0.5f ? 1.0f : -1.0f) * t.normal(k);
                if (glm::length(n) > 0.0f) {
                    const glm::vec3 p = (v0 + v1 + v2) / 3.0f;
                    b.push({offset_ray_origin(p, n), glm::normalize(n + 0.7f * random_unit(rng))}, 4.0f * glm::length(size));
                }
            }
        }
    }
    return b;
}

// rays_at_primitives plus uniformly random rays through the scene's box, unbounded or not.
inline RayBatch scene_rays(const Scene& scene, int random_count, uint32_t seed) {
    RayBatch b = rays_at_primitives(scene, random_count / 2, seed);
    std::mt19937 rng(seed + 1000);
    glm::vec3 lo, hi;
    scene_bounds(scene, lo, hi);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    for (int i = 0; i < random_count / 2; ++i) {
        const glm::vec3 o = lo + (hi - lo) * glm::vec3(u01(rng), u01(rng), u01(rng));
        b.push({o, random_unit(rng)}, 0.5f + 20.0f * u01(rng));
    }
    return b;
}

// The tree as data: its structure in preorder (child references, bounds, leaf contents), for
// comparing builds, and the invariants checked on the way.
struct BvhDump {
    std::vector<uint32_t> refs;
    std::vector<float> bounds;
    std::vector<uint32_t> primitive_ids;  // in leaf order
    std::vector<uint32_t> leaf_bits;      // every float of every leaf block, as bits, in leaf order
    std::size_t leaf_count = 0;
    uint32_t max_leaf_size = 0;
    bool parents_contain_children = true;
    bool leaves_one_kind = true;
    bool sphere_rows_past_id_zero = true;  // a sphere leaf's rows past its ids, unused, written as 0
    bool operator==(const BvhDump& o) const {
        return refs == o.refs && bounds == o.bounds && primitive_ids == o.primitive_ids && leaf_bits == o.leaf_bits;
    }
};

namespace detail {
struct Bounds {
    glm::vec3 lo{std::numeric_limits<float>::infinity()}, hi{-std::numeric_limits<float>::infinity()};
    void add(const glm::vec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
    bool inside(const glm::vec3& plo, const glm::vec3& phi) const {
        return glm::all(glm::greaterThanEqual(lo, plo)) && glm::all(glm::lessThanEqual(hi, phi));
    }
};

template <int W>
inline Bounds walk(const BvhView& v, uint32_t ref, BvhDump& out) {
    Bounds b;
    if (ref & kBvhLeafBit) {
        if (ref == kBvhEmptyChild) return b;
        const uint32_t kind = (ref >> kBvhKindShift) & 3u, first = ref & kBvhFirstMask;
        const uint32_t count = ((ref >> kBvhCountShift) & 7u) + 1u;
        ++out.leaf_count;
        out.max_leaf_size = std::max(out.max_leaf_size, count);
        out.leaves_one_kind &= kind <= uint32_t(BvhLeafKind::sphere);
        const bool sphere = kind == uint32_t(BvhLeafKind::sphere);
        const uint32_t rows = sphere ? kSphereRows : v.leaf_rows;
        const float* block = v.leaves + std::size_t(first) * v.leaf_rows;
        auto at = [&](uint32_t row, uint32_t lane) { return block[row * count + lane]; };
        auto vec = [&](uint32_t row, uint32_t lane) { return glm::vec3(at(row, lane), at(row + 1, lane), at(row + 2, lane)); };
        for (uint32_t i = 0; i < count * v.leaf_rows; ++i) {
            uint32_t bits;
            std::memcpy(&bits, block + i, sizeof bits);
            out.leaf_bits.push_back(bits);
            if (sphere && i >= kSphereRows * count) out.sphere_rows_past_id_zero &= bits == 0u;
        }
        for (uint32_t l = 0; l < count; ++l) {
            uint32_t id;
            const float id_bits = at(rows - 1, l);
            std::memcpy(&id, &id_bits, sizeof id);
            out.primitive_ids.push_back(id);
            if (sphere) {
                const float r = at(3, l);
                b.add(vec(0, l) - r), b.add(vec(0, l) + r);
            } else if (v.leaf_vertices) {
                b.add(vec(0, l)), b.add(vec(3, l)), b.add(vec(6, l));
            } else {
                const glm::vec3 v0 = vec(0, l), e1 = vec(3, l), e2 = vec(6, l);
                b.add(v0), b.add(v0 + e1), b.add(v0 + e2);
                if (kind == uint32_t(BvhLeafKind::parallelogram)) b.add(v0 + e1 + e2);
            }
        }
        return b;
    }
    const BvhNode<W>& node = static_cast<const BvhNode<W>*>(v.nodes)[ref];
    for (int c = 0; c < W; ++c) {
        out.refs.push_back(node.child[c]);
        for (int row = 0; row < 6; ++row) out.bounds.push_back(node.bounds[row][c]);
        if (node.child[c] == kBvhEmptyChild) continue;
        const glm::vec3 lo(node.bounds[0][c], node.bounds[2][c], node.bounds[4][c]);
        const glm::vec3 hi(node.bounds[1][c], node.bounds[3][c], node.bounds[5][c]);
        const Bounds child = walk<W>(v, node.child[c], out);
        out.parents_contain_children &= child.inside(lo, hi);
        b.add(lo), b.add(hi);
    }
    return b;
}
}  // namespace detail

inline BvhDump dump_bvh(const BvhView& v) {
    BvhDump out;
    out.refs.push_back(v.root);
    if (v.node_width == 4)
        detail::walk<4>(v, v.root, out);
    else
        detail::walk<8>(v, v.root, out);
    return out;
}

}  // namespace wt::test
