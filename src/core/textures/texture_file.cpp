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

std::shared_ptr<const TextureTexels> read_coverage_texture_file(const std::string& path, CoverageChannel channel) {
    const ImageData image = read_image(path, ImageLimits{kMaxTexturePixels, kMaxTextureSide});
    std::shared_ptr<const TextureTexels> texels = texels_of(image);
    const std::size_t n = image.channels.size();
    if (channel == CoverageChannel::automatic) {
        if (n == 2 || n >= 4) return texels;
        channel = CoverageChannel::luminance;
    }
    auto coverage = std::make_shared<TextureTexels>(*texels);
    for (glm::vec4& c : coverage->rgba) {
        switch (channel) {
            case CoverageChannel::red: c.w = c.x; break;
            case CoverageChannel::green: c.w = c.y; break;
            case CoverageChannel::blue: c.w = c.z; break;
            default: c.w = n <= 2 ? c.x : std::min(0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z, 1.0f); break;
        }
    }
    return coverage;
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
