#pragma once
// glTF 2.0 materials (metallic-roughness, and the transmission, ior and emissive-strength
// extensions) to ours.

#include <tiny_gltf.h>

#include "core/import/imported_mesh.h"

namespace wt {

// KHR_materials_transmission with a factor > 0: glass (ior from KHR_materials_ior, else 1.5).
// metallicFactor 1 and roughnessFactor 0: mirror with reflectance baseColorFactor. Otherwise
// Lambertian with albedo baseColorFactor. emissiveFactor (times emissiveStrength) is the
// emission. Textures, partial metalness and alpha are recorded as not mapped.
ImportedMaterial map_gltf_material(const tinygltf::Material& m);

}  // namespace wt
