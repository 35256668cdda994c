#include "core/film/image_input.h"

#include <cmath>
#include <filesystem>

#include <OpenImageIO/imageio.h>

namespace wt {

float srgb_to_linear(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

RgbImage read_rgb_image(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw ImageError(path + ": no such file");
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw ImageError(path + ": cannot read it as an image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    if (channels != 1 && channels < 3)
        throw ImageError(path + ": has " + std::to_string(channels) + " channels; expected 1 (grey) or at least 3 (RGB)");
    RgbImage image;
    image.width = spec.width;
    image.height = spec.height;
    std::vector<float> file_pixels(image.pixel_count() * std::size_t(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, file_pixels.data()))
        throw ImageError(path + ": reading failed: " + in->geterror());
    // Only integer formats carry a transfer curve here; float files are linear radiance whatever they say.
    const bool srgb = !spec.format.is_floating_point() && spec.get_string_attribute("oiio:ColorSpace") == "sRGB";

    image.rgb.resize(image.pixel_count() * 3);
    for (std::size_t p = 0; p < image.pixel_count(); ++p)
        for (int c = 0; c < 3; ++c) {
            const float v = file_pixels[p * std::size_t(channels) + std::size_t(channels == 1 ? 0 : c)];
            if (!std::isfinite(v))
                throw ImageError(path + ": pixel (" + std::to_string(p % std::size_t(image.width)) + "," +
                                 std::to_string(p / std::size_t(image.width)) + ") channel " + std::to_string(c) +
                                 " is " + std::to_string(v) + ", not a finite number");
            image.rgb[p * 3 + std::size_t(c)] = srgb ? srgb_to_linear(v) : v;
        }
    return image;
}

}  // namespace wt
