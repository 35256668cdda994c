// Closed meshes shot from inside with rays aimed exactly at their vertices and along their
// shared edges, where Moller-Trumbore's independent per-triangle rounding can let a ray slip
// between two triangles. The watertight test must let none escape, on every ISA; the
// Moller-Trumbore escape rate is printed, and must not be zero (else the rays miss the edges).

#include <cstdio>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

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

Escapes count_escapes(const Scene& scene, const std::vector<Ray>& rays, Isa isa) {
    std::vector<float> ox, oy, oz, dx, dy, dz;
    for (const Ray& r : rays) {
        ox.push_back(r.origin.x), oy.push_back(r.origin.y), oz.push_back(r.origin.z);
        dx.push_back(r.direction.x), dy.push_back(r.direction.y), dz.push_back(r.direction.z);
    }
    const std::size_t n = rays.size();
    std::vector<float> t(n), u(n), v(n);
    std::vector<uint32_t> prim(n);
    const IntersectKernels& k = intersect_kernels(isa, scene.settings.accuracy);
    k.closest_raypacket(scene_view(scene), {ox.data(), oy.data(), oz.data(), dx.data(), dy.data(), dz.data(), nullptr, uint32_t(n)},
                        {t.data(), u.data(), v.data(), prim.data()});
    Escapes e;
    e.total = n;
    for (std::size_t i = 0; i < n; ++i) e.escaped += prim[i] == kNoHit;
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
        for (Isa isa : {Isa::scalar, Isa::sse4, Isa::avx2, Isa::avx512}) {
            if (!cpu_supports(isa)) continue;
            EXPECT_EQ(count_escapes(watertight, rays, isa).escaped, 0u) << c.name << " " << isa_name(isa);
        }
        // The other side: Moller-Trumbore must let some through, or the rays no longer aim at the
        // edges and vertices, and the watertight result above would prove nothing. Every ISA
        // lets the same rays through (the kernels return the scalar code's bits).
        const Escapes mt = count_escapes(moller, rays, Isa::scalar);
        EXPECT_GT(mt.escaped, 0u) << c.name << ": no ray escapes even Moller-Trumbore; are the rays still aimed at edges?";
        for (Isa isa : {Isa::sse4, Isa::avx2, Isa::avx512})
            if (cpu_supports(isa)) EXPECT_EQ(count_escapes(moller, rays, isa).escaped, mt.escaped) << c.name << " " << isa_name(isa);
        std::printf("%-14s %zu triangles: Moller-Trumbore lets %zu of %zu vertex/edge rays escape (%.3f%%); watertight 0\n",
                    c.name, c.mesh.triangles.size(), mt.escaped, mt.total, 100.0 * double(mt.escaped) / double(mt.total));
    }
}

}  // namespace
}  // namespace wt
