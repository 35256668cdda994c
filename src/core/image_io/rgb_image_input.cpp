#include "core/image_io/rgb_image_input.h"

#include <cmath>
#include <filesystem>

#include "core/image_io/image_input.h"

namespace wt {

float srgb_to_linear(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

RgbImage read_rgb_image(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw ImageError(path + ": no such file");
    ImageData file;
    try {
        file = read_image(path);
    } catch (const ImageError& e) {
        throw ImageError(path + ": cannot read it as an image: " + e.what());
    }
    const int channels = int(file.channels.size());
    if (channels != 1 && channels < 3)
        throw ImageError(path + ": has " + std::to_string(channels) + " channels; expected 1 (grey) or at least 3 (RGB)");
    int source[3] = {0, 0, 0};
    if (channels >= 3) {
        const int r = file.channel_index("R"), g = file.channel_index("G"), b = file.channel_index("B");
        const bool named = r >= 0 && g >= 0 && b >= 0;
        source[0] = named ? r : 0, source[1] = named ? g : 1, source[2] = named ? b : 2;
    }
    // Only our PNGs (and other integer files marked so) carry the sRGB curve; float files are
    // linear radiance.
    const bool srgb = file.attribute("oiio:ColorSpace").value_or("") == "sRGB";
    RgbImage image;
    image.width = file.width;
    image.height = file.height;
    image.rgb.resize(image.pixel_count() * 3);
    for (std::size_t p = 0; p < image.pixel_count(); ++p)
        for (int c = 0; c < 3; ++c) {
            const float v = file.pixels[p * std::size_t(channels) + std::size_t(source[c])];
            if (!std::isfinite(v))
                throw ImageError(path + ": pixel (" + std::to_string(p % std::size_t(image.width)) + "," +
                                 std::to_string(p / std::size_t(image.width)) + ") channel " + std::to_string(c) +
                                 " is " + std::to_string(v) + ", not a finite number");
            image.rgb[p * 3 + std::size_t(c)] = srgb ? srgb_to_linear(v) : v;
        }
    return image;
}

}  // namespace wt
