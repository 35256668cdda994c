#include "core/import/obj_textures.h"

#include <memory>

#include "core/image_io/image_error.h"

namespace wt {

std::string ObjTextures::resolved(const std::string& file) const {
    const std::filesystem::path relative(file);
    return relative.is_absolute() ? file : (base_dir_ / relative).string();
}

int ObjTextures::once(const std::string& key, const std::function<TextureImage()>& make) {
    if (!read_) return -1;
    if (const auto it = index_of_.find(key); it != index_of_.end()) return it->second;
    out_.push_back(make());
    return index_of_[key] = int(out_.size() - 1);
}

int ObjTextures::add_color(const std::string& file) {
    const std::string path = resolved(file);
    return once("colour\n" + path, [&] {
        TextureImage image;
        image.name = path;
        image.srgb = colour_file_is_srgb(path);
        image.texels = read_texture_file(path);
        return image;
    });
}

int ObjTextures::add_coverage(const ScalarMap& map) {
    const std::string path = resolved(map.file);
    return once("coverage " + std::to_string(int(map.channel)) + "\n" + path, [&] {
        TextureImage image;
        image.name = path;
        image.srgb = false;  // data, as alpha always is
        image.texels = read_scalar_texture_file(path, map.channel);
        return image;
    });
}

int ObjTextures::add_metallic_roughness(const ScalarMap& roughness, const ScalarMap& metallic) {
    const std::string r_path = roughness.file.empty() ? "" : resolved(roughness.file);
    const std::string m_path = metallic.file.empty() ? "" : resolved(metallic.file);
    const std::string key = "metallic-roughness " + std::to_string(int(roughness.channel)) + " " +
                            std::to_string(int(metallic.channel)) + "\n" + r_path + "\n" + m_path;
    return once(key, [&] {
        std::shared_ptr<const TextureTexels> r, m;
        if (!r_path.empty()) r = read_scalar_texture_file(r_path, roughness.channel);
        if (!m_path.empty()) m = read_scalar_texture_file(m_path, metallic.channel);
        if (r && m && (r->width != m->width || r->height != m->height))
            throw ImageError(r_path + " (" + std::to_string(r->width) + " x " + std::to_string(r->height) + ") and " + m_path +
                             " (" + std::to_string(m->width) + " x " + std::to_string(m->height) +
                             ") differ in size; map_Pr and map_Pm are read texel for texel");
        const TextureTexels& shape = r ? *r : *m;
        auto texels = std::make_shared<TextureTexels>();
        texels->width = shape.width, texels->height = shape.height;
        texels->rgba.resize(shape.rgba.size());
        for (std::size_t p = 0; p < texels->rgba.size(); ++p)
            texels->rgba[p] = glm::vec4(0.0f, r ? r->rgba[p].x : 1.0f, m ? m->rgba[p].x : 1.0f, 1.0f);
        TextureImage image;
        image.name = r_path.empty() ? m_path : (m_path.empty() ? r_path : r_path + " + " + m_path);
        image.srgb = false;
        image.texels = std::move(texels);
        return image;
    });
}

}  // namespace wt
