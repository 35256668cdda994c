#pragma once
// The description's prototypes and instances as the scene stores them (scene_instances.h).

#include <cstdint>
#include <string>

#include <glm/mat4x4.hpp>

#include "core/instances/scene_instances.h"
#include "core/description/scene_description.h"

namespace wt {

// Empty when m can place an instance: finite, affine, invertible, it and its inverse finite in
// float. Otherwise what is wrong with it ("is singular (determinant 0)"), for messages.
std::string instance_transform_problem(const glm::dmat4& m);

// Ids from first_id on (the scene's own triangles and spheres come first). Throws
// std::invalid_argument for a bad transform, a missing prototype, an emissive prototype (the
// light table lists the scene's own triangles) or more triangles than 32-bit ids can name.
void build_instances(const SceneDescription& description, uint32_t first_id, SceneInstances& out);

}  // namespace wt
