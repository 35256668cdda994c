#pragma once
// MTL materials (as tinyobjloader reads them) to ours.

#include <tiny_obj_loader.h>

#include "core/import/imported_mesh.h"

namespace wt {

// illum 3 or 5 (ray-traced reflection): mirror with reflectance Ks. illum 4, 6 or 7
// (refraction): glass with ior Ni. Otherwise Lambertian with albedo Kd. Ke is the emission.
// Texture maps are recorded as not mapped.
ImportedMaterial map_obj_material(const tinyobj::material_t& m);

}  // namespace wt
