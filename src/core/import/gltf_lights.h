#pragma once
// glTF's KHR_lights_punctual (point, spot, directional) as the scene's "lights" list: a node
// that names a light places it, at the node's world origin and pointing along its -Z.

#include <string>

#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>

#include "core/import/imported_mesh.h"

namespace wt {

// Light `index` of the file's KHR_lights_punctual, placed by `world` (the node's transform),
// appended to mesh.lights; notes (an ignored range, a light without light) to mesh.notes.
// Photometric to radiometric at 683 lm/W (the luminous efficacy of 555 nm light, which defines
// the candela): intensity in candela becomes W/sr, a directional light's lux W/m². A spot's
// innerConeAngle and outerConeAngle (half angles, radians) become cone_degrees = 2 outer and
// blend = 1 - inner / outer. Throws MeshFileError naming `path` and the light for a light that
// does not exist, an unknown type, a negative or non-finite colour or intensity, or cone angles
// outside 0 <= inner < outer <= pi / 2.
void read_gltf_light(const std::string& path, const tinygltf::Model& model, int index, const glm::dmat4& world,
                     ImportedMesh& mesh);

// The light index a node names through KHR_lights_punctual, or -1.
int gltf_node_light(const tinygltf::Node& node);

}  // namespace wt
