#include "core/image_io/image_input.h"

#include <algorithm>
#include <memory>

#include "core/image_io/image_module.h"

namespace wt {

int ImageData::channel_index(const std::string& name) const {
    const auto it = std::find(channels.begin(), channels.end(), name);
    return it == channels.end() ? -1 : int(it - channels.begin());
}

float ImageData::value(const std::string& name, int x, int y) const {
    const int c = channel_index(name);
    if (c < 0) throw ImageError("image has no channel '" + name + "'");
    return pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * channels.size() + std::size_t(c)];
}

std::vector<float> ImageData::channel(const std::string& name) const {
    const int c = channel_index(name);
    if (c < 0) throw ImageError("image has no channel '" + name + "'");
    std::vector<float> out(std::size_t(width) * std::size_t(height));
    for (std::size_t p = 0; p < out.size(); ++p) out[p] = pixels[p * channels.size() + std::size_t(c)];
    return out;
}

std::optional<std::string> ImageData::attribute(const std::string& name) const {
    for (const auto& [key, value] : attributes)
        if (key == name) return value;
    return std::nullopt;
}

namespace {

ImageData read_source(const WtImageSource& source) {
    const WtImageModuleApi& module = image_module();
    WtReadImage raw{};
    char error[1024];
    if (module.read_image_source(&source, &raw, error, sizeof error) != 0) throw ImageError(error);
    const auto release = [&](WtReadImage* r) { module.free_image(r); };
    std::unique_ptr<WtReadImage, decltype(release)> guard(&raw, release);

    ImageData image;
    image.width = raw.width, image.height = raw.height;
    image.channels.assign(raw.channel_names, raw.channel_names + raw.channels);
    image.pixels.assign(raw.pixels, raw.pixels + std::size_t(raw.width) * std::size_t(raw.height) * std::size_t(raw.channels));
    for (int i = 0; i < raw.attribute_count; ++i) image.attributes.emplace_back(raw.attribute_names[i], raw.attribute_values[i]);
    return image;
}

}  // namespace

ImageData read_image(const std::string& path) { return read_image(path, ImageLimits{}); }

ImageData read_image(const std::string& path, ImageLimits limits) {
    return read_source(WtImageSource{path.c_str(), nullptr, 0, limits.max_pixels, limits.max_side});
}

ImageData read_image_bytes(const std::string& name, const void* bytes, std::size_t size, ImageLimits limits) {
    // A null pointer would mean "the file at name": an empty buffer is still a buffer.
    static const unsigned char kNothing = 0;
    return read_source(WtImageSource{name.c_str(), bytes ? bytes : &kNothing, bytes ? size : 0, limits.max_pixels,
                                     limits.max_side});
}

}  // namespace wt
