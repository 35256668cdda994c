#pragma once
// The big meshes bench_intersect measures the BVH on: a UV sphere whose radius is displaced by
// a smooth function of the direction, so the triangles vary in size and orientation the way a
// scanned or sculpted model's do, while the mesh stays closed (rays starting outside its
// bounding ball never start inside it) and any size is one formula away.
//
// Deterministic: the same shape gives the same floats on every run (computed in double,
// rounded once).

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/description/scene_description.h"

namespace wt::bench {

struct DisplacedSphereShape {
    int segments_u = 100;  // around the polar (z) axis, at least 3
    int segments_v = 50;   // from the north pole to the south pole, at least 2
    glm::vec3 centre{0.0f};
    float radius = 1.0f;
    float amplitude = 0.0f;  // the radius varies by at most +-amplitude, below radius
};

// segments_u triangles in each polar fan, two per quad in the segments_v - 2 bands between them.
std::size_t displaced_sphere_triangle_count(const DisplacedSphereShape& shape);
// Two poles and segments_v - 1 rings of segments_u vertices.
std::size_t displaced_sphere_vertex_count(const DisplacedSphereShape& shape);

// The mesh, wound counter-clockwise seen from outside (geometric normals point out), with
// analytic unit shading normals (from the displacement's gradient, not averaged face normals)
// in `normals`. Vertex 0 is the north pole (+z), the last the south pole; ring j (1 ...
// segments_v - 1) is at polar angle pi j / segments_v, its vertex i at azimuth
// 2 pi i / segments_u. The poles are triangle fans, so no triangle is degenerate.
// Throws std::invalid_argument for segment counts or an amplitude outside the ranges above.
TriangleMesh displaced_sphere(const DisplacedSphereShape& shape, uint32_t material);

// The displacement, in [-1, 1], at the point (x, y, z) of the unit sphere: a third of a sum of
// three sines of linear functions of the coordinates, smooth everywhere, the poles included
// (a function of the spherical angles would have a kink there unless it flattened out).
double displacement(double x, double y, double z);

// --- The benchmark meshes ---

// Centre (5, 0, 1.5), radius 2, amplitude 0.2: in the hexroom's air above the floor objects,
// below the light, clear of the spheres.
DisplacedSphereShape benchmark_sphere(int segments_u, int segments_v);
// Radius + amplitude: no point of a benchmark sphere is farther from its centre.
constexpr float kBenchmarkSphereBoundingRadius = 2.2f;
const glm::vec3 kBenchmarkSphereCentre{5.0f, 0.0f, 1.5f};

struct BenchmarkMesh {
    const char* name;  // the mesh file's stem and material; the scene is "hexroom_" + name
    int segments_u, segments_v;
};
// 9,800, 99,224 and 996,000 triangles.
constexpr BenchmarkMesh kBenchmarkMeshes[] = {{"mesh10k", 100, 50}, {"mesh100k", 316, 158}, {"mesh1m", 1000, 499}};

}  // namespace wt::bench
