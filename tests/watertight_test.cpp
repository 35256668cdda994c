// Closed meshes shot from inside with rays aimed exactly at their vertices and along their
// shared edges, where Moller-Trumbore's independent per-triangle rounding can let a ray slip
// between two triangles. The watertight test must let none escape, on every ISA; the
// Moller-Trumbore escape rate is printed, and must not be zero (else the rays miss the edges).

#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/accuracy.h"
#include "core/base/ray_offset.h"
#include "core/scene/scene.h"
#include "kernels/isa/intersect_dispatch.h"
#include "test_scenes.h"

namespace wt {
namespace {

// Vertices and triangles; material 0, no vertex normals.
using Mesh = TriangleMesh;

using test::icosphere;

// The cube [lo, hi]^3 with each face split into n x n quads (2 triangles each), sharing vertices.
Mesh split_cube(int n, glm::vec3 lo, glm::vec3 hi) {
    Mesh m;
    std::map<std::array<int, 3>, uint32_t> index;
    auto vertex = [&](int i, int j, int k) {
        const std::array<int, 3> key{i, j, k};
        auto it = index.find(key);
        if (it != index.end()) return it->second;
        m.vertices.push_back(lo + (hi - lo) * glm::vec3(i, j, k) / float(n));
        return index[key] = uint32_t(m.vertices.size() - 1);
    };
    for (int axis = 0; axis < 3; ++axis) {
        for (int side : {0, n}) {
            for (int a = 0; a < n; ++a) {
                for (int b = 0; b < n; ++b) {
                    auto at = [&](int u, int v) {
                        std::array<int, 3> c{};
                        c[axis] = side, c[(axis + 1) % 3] = u, c[(axis + 2) % 3] = v;
                        return vertex(c[0], c[1], c[2]);
                    };
                    const uint32_t p00 = at(a, b), p10 = at(a + 1, b), p11 = at(a + 1, b + 1), p01 = at(a, b + 1);
                    m.triangles.push_back({p00, p10, p11}), m.triangles.push_back({p00, p11, p01});
                }
            }
        }
    }
    return m;
}

Scene scene_of(const Mesh& mesh, TriangleTest test) {
    SceneDescription d;
    d.materials.resize(1);
    d.meshes.push_back(mesh);
    d.settings.accuracy.triangles = test;
    return build_scene(d);
}

// Rays from a few interior points to every vertex and to points along every edge.
std::vector<Ray> rays_at_vertices_and_edges(const Mesh& mesh, const std::vector<glm::vec3>& origins) {
    std::vector<Ray> rays;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const glm::vec3& o : origins) {
        for (const glm::vec3& v : mesh.vertices) rays.push_back({o, glm::normalize(v - o)});
        for (const auto& tri : mesh.triangles) {
            for (int e = 0; e < 3; ++e) {
                const glm::vec3 a = mesh.vertices[tri[e]], b = mesh.vertices[tri[(e + 1) % 3]];
                for (float s : {0.5f, u(rng), u(rng)}) rays.push_back({o, glm::normalize(a + s * (b - a) - o)});
            }
        }
    }
    return rays;
}

struct Escapes {
    std::size_t escaped = 0, total = 0;
};

// The closest hit of every ray through one ISA's packet kernel (prim kNoHit for a miss).
std::vector<Hit> closest_hits(const Scene& scene, const std::vector<Ray>& rays, Isa isa) {
    std::vector<float> ox, oy, oz, dx, dy, dz;
    for (const Ray& r : rays) {
        ox.push_back(r.origin.x), oy.push_back(r.origin.y), oz.push_back(r.origin.z);
        dx.push_back(r.direction.x), dy.push_back(r.direction.y), dz.push_back(r.direction.z);
    }
    const std::size_t n = rays.size();
    std::vector<float> t(n), u(n), v(n);
    std::vector<uint32_t> prim(n);
    const IntersectKernels& k = intersect_kernels(isa, scene.settings.accuracy);
    k.closest_raypacket(FlatScene(scene).view(), {ox.data(), oy.data(), oz.data(), dx.data(), dy.data(), dz.data(), nullptr, uint32_t(n)},
                        {t.data(), u.data(), v.data(), prim.data()});
    std::vector<Hit> hits(n);
    for (std::size_t i = 0; i < n; ++i) hits[i].t = t[i], hits[i].u = u[i], hits[i].v = v[i], hits[i].prim = prim[i];
    return hits;
}

Escapes count_escapes(const Scene& scene, const std::vector<Ray>& rays, Isa isa) {
    Escapes e;
    e.total = rays.size();
    for (const Hit& h : closest_hits(scene, rays, isa)) e.escaped += h.prim == kNoHit;
    return e;
}

struct ClosedMeshCase {
    const char* name;
    Mesh mesh;
    std::vector<glm::vec3> origins;
};

std::vector<ClosedMeshCase> closed_meshes() {
    return {{"icosphere", icosphere(3, 3.0f, {1.0f, -2.0f, 0.5f}), {{1.0f, -2.0f, 0.5f}, {1.7f, -1.1f, -0.3f}}},
            {"split_cube", split_cube(8, {-1.0f, -2.0f, -3.0f}, {2.0f, 1.0f, 0.0f}),
             {{0.5f, -0.5f, -1.5f}, {0.1f, 0.7f, -2.2f}}},
            {"far_icosphere", icosphere(2, 1.0f, {1000.0f, 2000.0f, -500.0f}), {{1000.2f, 1999.9f, -500.1f}}}};
}

TEST(Watertight, NoRayEscapesAClosedMeshOnAnyIsa) {
    for (const ClosedMeshCase& c : closed_meshes()) {
        const std::vector<Ray> rays = rays_at_vertices_and_edges(c.mesh, c.origins);
        const Scene watertight = scene_of(c.mesh, TriangleTest::watertight);
        const Scene moller = scene_of(c.mesh, TriangleTest::moller_trumbore);
        for (Isa isa : kAllIsas) {
            if (!cpu_supports(isa)) continue;
            EXPECT_EQ(count_escapes(watertight, rays, isa).escaped, 0u) << c.name << " " << isa_name(isa);
        }
        // The other side: Moller-Trumbore must let some through, or the rays no longer aim at the
        // edges and vertices, and the watertight result above would prove nothing. Every ISA
        // lets the same rays through (the kernels return the scalar code's bits).
        const Escapes mt = count_escapes(moller, rays, Isa::scalar);
        EXPECT_GT(mt.escaped, 0u) << c.name << ": no ray escapes even Moller-Trumbore; are the rays still aimed at edges?";
        for (Isa isa : {Isa::sse4, Isa::avx2, Isa::avx512})
            if (cpu_supports(isa)) {
                EXPECT_EQ(count_escapes(moller, rays, isa).escaped, mt.escaped) << c.name << " " << isa_name(isa);
            }
        std::printf("%-14s %zu triangles: Moller-Trumbore lets %zu of %zu vertex/edge rays escape (%.3f%%); watertight 0\n",
                    c.name, c.mesh.triangles.size(), mt.escaped, mt.total, 100.0 * double(mt.escaped) / double(mt.total));
    }
}


// Rays spawned where rays from inside hit the faces x = 0, y = 0 and z = 0 of a box, as the
// renderer spawns them (surface_at, then offset_ray_origin), must not hit the face they leave.
// On an axis-aligned plane through 0 the hit point's error bound is 0 along the normal, so the
// watertight test needs its floor on that bound (with_watertight_floor, core/base/ray_offset.h):
// without it many such rays met their own wall at a t of a few ulps, and a room with walls on
// x = 0 and z = 0 rendered too dark.
// The other side: the same rays started at the hit points themselves, not moved off, do hit
// their faces again, so these rays exercise what the offset has to solve.
TEST(Watertight, NoSpawnedRayHitsTheFaceItLeavesOnAnyIsa) {
    const glm::vec3 size(2.0f, 3.0f, 1.5f);
    const Mesh box = split_cube(4, {0.0f, 0.0f, 0.0f}, size);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Ray> to_faces;
    for (int i = 0; i < 3000; ++i) {
        const int axis = i % 3;
        glm::vec3 aim = size * (0.1f + 0.8f * glm::vec3(u(rng), u(rng), u(rng)));  // 0.15 or more from other faces
        aim[axis] = 0.0f;
        const glm::vec3 from = size * (0.3f + 0.4f * glm::vec3(u(rng), u(rng), u(rng)));
        to_faces.push_back({from, glm::normalize(aim - from)});
    }
    for (TriangleTest test : {TriangleTest::watertight, TriangleTest::moller_trumbore}) {
        const Scene scene = scene_of(box, test);
        for (Isa isa : kAllIsas) {
            if (!cpu_supports(isa)) continue;
            const std::vector<Hit> hits = closest_hits(scene, to_faces, isa);
            std::vector<Ray> spawned, unmoved;
            for (std::size_t i = 0; i < hits.size(); ++i) {
                ASSERT_NE(hits[i].prim, kNoHit);
                const SurfacePoint s = surface_at(scene, to_faces[i], hits[i]);
                const glm::vec3 inward = glm::dot(s.normal, to_faces[i].direction) < 0.0f ? s.normal : -s.normal;
                glm::vec3 d(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
                d += (0.05f + u(rng) - glm::dot(d, inward)) * inward;  // into the box, up to grazing
                d = glm::normalize(d);
                spawned.push_back({offset_ray_origin(s.position, s.error, inward), d});
                unmoved.push_back({s.position, d});
            }
            auto self_hits = [&](const std::vector<Ray>& rays) {
                std::size_t n = 0;
                for (const Hit& h : closest_hits(scene, rays, isa)) n += h.prim != kNoHit && !(h.t > 0.1f);  // other faces: >= 0.15 away
                return n;
            };
            EXPECT_EQ(self_hits(spawned), 0u) << name_of(test) << " " << isa_name(isa) << ": spawned rays that hit their own face";
            if (test == TriangleTest::watertight) {
                EXPECT_GT(self_hits(unmoved), 0u) << isa_name(isa) << ": rays started on their faces never hit them; the test proves nothing";
            }
        }
    }
}

}  // namespace
}  // namespace wt
