#pragma once
// MTL files, read by tinyobjloader, and their materials mapped to ours.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <tiny_obj_loader.h>

#include "core/import/imported_mesh.h"
#include "core/textures/texture_file.h"

namespace wt {

// illum 3 or 5 (ray-traced reflection): mirror with reflectance Ks. illum 4, 6 or 7
// (refraction): glass with ior Ni, rough at Pr > 0. Otherwise, with the PBR extension's Pr or
// Pm (either non-zero), glTF's metallic-roughness material of base colour Kd; with a highlight
// (illum 2 or above and Ks not black) that material as a plastic, metallic 0 and roughness from
// Ns; else Lambertian with albedo Kd. Ke is the emission. map_Kd multiplies Kd (the albedo or
// the base colour), read relative to the OBJ file's directory through `textures`; a texture that
// cannot be read is a MeshFileError naming `obj_path`, the material and map_Kd. The other maps
// are recorded as not mapped.
class ObjTextures;
ImportedMaterial map_obj_material(const tinyobj::material_t& m, const std::string& obj_path, ObjTextures& textures);

// The images an OBJ's materials name, each file read once, appended to `out`.
class ObjTextures {
public:
    // read: whether the file's materials are used (MeshFileUse::file_materials).
    ObjTextures(const std::filesystem::path& base_dir, std::vector<TextureImage>& out, bool read)
        : base_dir_(base_dir), out_(out), read_(read) {}
    // Index in `out` of a colour texture of `file` (-1 if not `read`); throws ImageError naming the file.
    int add_color(const std::string& file);
    // Index in `out` of `file`'s `channel` read as coverage for the alpha test
    // (read_coverage_texture_file); -1 if not `read`; throws ImageError naming the file.
    int add_coverage(const std::string& file, CoverageChannel channel);

private:
    // What a file is read as: colour, or coverage from one of its channels.
    using Use = std::optional<CoverageChannel>;
    int add(const std::string& file, Use use);

    std::filesystem::path base_dir_;
    std::vector<TextureImage>& out_;
    std::map<std::pair<std::string, Use>, int> index_of_;  // a file used both ways is two textures
    bool read_;
};

// Appends the materials of the MTL file at `path` to `materials`, and their names to `ids` (a
// name defined twice keeps its first index). The file is read whole, so only a regular file
// within the scene-file limit (`mtllib /dev/zero` would otherwise be read without end).
// Returns "" or, if the file cannot be read, why ("PATH: cannot open: ...").
std::string read_mtl_file(const std::string& path, std::vector<tinyobj::material_t>& materials,
                          std::map<std::string, int>& ids);

}  // namespace wt
