#pragma once
// Per-corner tangents for normal maps by Mikkelsen's MikkTSpace (M. Mikkelsen, "Simulation of
// wrinkled surfaces revisited", 2008; the reference mikktspace.c), which glTF 2.0 (3.7.2.1)
// asks a client to compute where a normal-mapped primitive has no TANGENT: a baker that used
// the same frame then gives back the normal it baked.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace wt {

// One tangent per triangle corner (3 t + c), xyz unit and orthogonal to the corner's normal,
// w = +1 or -1 the bitangent's side: bitangent = cross(normal, xyz) w, as glTF's TANGENT.
// The tangent follows +u and the bitangent -v (glTF's images have v = 0 at the top and their
// normal maps +y up). `normals` may be empty (then each face's own normal). Always finite: a
// corner with no usable mapping around it gets some unit vector orthogonal to its normal.
std::vector<glm::vec4> mikktspace_tangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                           const std::vector<glm::vec2>& uvs,
                                           const std::vector<std::array<uint32_t, 3>>& triangles);

}  // namespace wt
