#pragma once
// Smooth shading normals for a mesh that has none.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace wt {

// One unit normal per vertex: the sum of the unit normals of the triangles around it, each
// weighted by the triangle's angle at that vertex (Thürmer and Wüthrich 1998), so the result
// does not depend on how the surface around the vertex is cut into triangles. Vertices are
// joined by index, not position: a seam the file split stays a crease. A vertex no triangle
// uses gets +z; one whose weighted normals cancel gets the normal of a triangle around it.
std::vector<glm::vec3> angle_weighted_normals(const std::vector<glm::vec3>& positions,
                                              const std::vector<std::array<uint32_t, 3>>& triangles);

}  // namespace wt
