#pragma once
// The images an OBJ's MTL materials name, each file read once per use and appended to the mesh's
// textures: colour maps (map_Kd), coverage (map_d) and the PBR extension's scalar maps (map_Pr,
// map_Pm) assembled into the metallic-roughness layout the shade stage reads for glTF.

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/textures/texture_file.h"
#include "core/textures/texture_image.h"

namespace wt {

// A scalar map: its file (relative to the OBJ's directory, or absolute) and the channel read.
struct ScalarMap {
    std::string file;  // empty: no map
    ScalarChannel channel = ScalarChannel::luminance;
};

class ObjTextures {
public:
    // read: whether the file's materials are used (MeshFileUse::file_materials); if not, nothing
    // is read and every index is -1.
    ObjTextures(const std::filesystem::path& base_dir, std::vector<TextureImage>& out, bool read)
        : base_dir_(base_dir), out_(out), read_(read) {}

    // Each returns the texture's index in `out` and throws ImageError naming the file.
    int add_color(const std::string& file);
    // The map's value in every channel, of which the alpha test reads the fourth.
    int add_coverage(const ScalarMap& map);
    // Roughness in green and metallic in blue, as glTF's metallicRoughnessTexture (3.9.2); a
    // missing map's channel is 1, so its factor alone counts. Both maps given must have the same
    // size (an ImageError naming both says so): texel for texel is the only way two files make
    // one texture without resampling either.
    int add_metallic_roughness(const ScalarMap& roughness, const ScalarMap& metallic);

private:
    std::string resolved(const std::string& file) const;
    // The texture `key` names, made by `make` the first time.
    int once(const std::string& key, const std::function<TextureImage()>& make);

    std::filesystem::path base_dir_;
    std::vector<TextureImage>& out_;
    std::map<std::string, int> index_of_;  // by what is read how: a file used two ways is two textures
    bool read_;
};

}  // namespace wt
