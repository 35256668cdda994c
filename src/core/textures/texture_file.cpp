#include "core/textures/texture_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace wt {

std::shared_ptr<const TextureTexels> texels_of(const ImageData& image) {
    auto t = std::make_shared<TextureTexels>();
    t->width = image.width, t->height = image.height;
    const std::size_t n = image.channels.size();
    t->rgba.resize(std::size_t(image.width) * std::size_t(image.height));
    for (std::size_t p = 0; p < t->rgba.size(); ++p) {
        const float* c = &image.pixels[p * n];
        if (n == 1) t->rgba[p] = glm::vec4(c[0], c[0], c[0], 1.0f);
        else if (n == 2) t->rgba[p] = glm::vec4(c[0], c[0], c[0], c[1]);
        else if (n == 3) t->rgba[p] = glm::vec4(c[0], c[1], c[2], 1.0f);
        else t->rgba[p] = glm::vec4(c[0], c[1], c[2], c[3]);
    }
    return t;
}

std::shared_ptr<const TextureTexels> read_texture_file(const std::string& path) {
    return texels_of(read_image(path, ImageLimits{kMaxTexturePixels, kMaxTextureSide}));
}

std::shared_ptr<const TextureTexels> read_scalar_texture_file(const std::string& path, ScalarChannel channel) {
    const ImageData image = read_image(path, ImageLimits{kMaxTexturePixels, kMaxTextureSide});
    const std::size_t n = image.channels.size();
    if (channel == ScalarChannel::alpha_else_luminance) channel = n == 2 || n >= 4 ? ScalarChannel::alpha : ScalarChannel::luminance;
    auto texels = std::make_shared<TextureTexels>(*texels_of(image));
    for (glm::vec4& c : texels->rgba) {
        float value = c.w;
        switch (channel) {
            case ScalarChannel::red: value = c.x; break;
            case ScalarChannel::green: value = c.y; break;
            case ScalarChannel::blue: value = c.z; break;
            case ScalarChannel::luminance: value = n <= 2 ? c.x : std::min(0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z, 1.0f); break;
            default: break;  // alpha
        }
        c = glm::vec4(value);
    }
    return texels;
}

bool colour_file_is_srgb(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext != ".exr" && ext != ".hdr";
}

std::shared_ptr<const TextureTexels> read_texture_bytes(const std::string& name, const void* bytes, std::size_t size) {
    return texels_of(read_image_bytes(name, bytes, size, ImageLimits{kMaxTexturePixels, kMaxTextureSide}));
}

}  // namespace wt
