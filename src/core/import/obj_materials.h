#pragma once
// MTL files, read by tinyobjloader, and their materials mapped to ours.

#include <map>
#include <string>
#include <vector>

#include <tiny_obj_loader.h>

#include "core/import/imported_mesh.h"
#include "core/import/obj_textures.h"

namespace wt {

// illum 3 or 5 (ray-traced reflection): mirror with reflectance Ks. illum 4, 6 or 7
// (refraction): glass with ior Ni, rough at Pr > 0. Otherwise, with the PBR extension's Pr or
// Pm (either non-zero) or its maps map_Pr or map_Pm, glTF's metallic-roughness material of base
// colour Kd; with a highlight (illum 2 or above and Ks not black) that material as a plastic,
// metallic 0 and roughness from Ns; else Lambertian with albedo Kd. Ke is the emission (map_Ke in its place). map_Kd
// multiplies Kd (the albedo or the base colour); map_Pr and map_Pm replace Pr and Pm (as
// Blender's importer links them in place of the values); d times map_d is alpha (README, Alpha).
// Maps are read relative to the OBJ file's directory through `textures`; one that cannot be read
// is a MeshFileError naming `obj_path`, the material and the map. The other maps are recorded as
// not mapped.
ImportedMaterial map_obj_material(const tinyobj::material_t& m, const std::string& obj_path, ObjTextures& textures);

// Appends the materials of the MTL file at `path` to `materials`, and their names to `ids` (a
// name defined twice keeps its first index). The file is read whole, so only a regular file
// within the scene-file limit (`mtllib /dev/zero` would otherwise be read without end).
// Returns "" or, if the file cannot be read, why ("PATH: cannot open: ...").
std::string read_mtl_file(const std::string& path, std::vector<tinyobj::material_t>& materials,
                          std::map<std::string, int>& ids);

}  // namespace wt
