#pragma once
// glTF 2.0 materials (metallic-roughness, and the transmission, ior and emissive-strength
// extensions) to ours.

#include <tiny_gltf.h>

#include <string>

#include "core/import/gltf_textures.h"
#include "core/import/imported_mesh.h"

namespace wt {

// KHR_materials_transmission with a factor > 0: glass, rough at roughnessFactor > 0 (ior from
// KHR_materials_ior, else 1.5). Otherwise the metallic-roughness material itself (principled,
// core/materials/principled.h) from baseColorFactor, metallicFactor, roughnessFactor and the
// ior, which with metallic 1 is the conductor of F0 baseColorFactor. emissiveFactor (times
// emissiveStrength) is the emission. baseColorTexture (on TEXCOORD_0 or 1) multiplies the base
// colour, added to `textures`; `name` is the material's, for errors. Other textures, alpha and
// partial transmission are recorded as not mapped; doubleSided is not read (both sides of every
// surface scatter, as in Cycles).
ImportedMaterial map_gltf_material(const tinygltf::Material& m, const std::string& name, GltfTextures& textures);

}  // namespace wt
