#include "core/film/image_output.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>

#include <OpenImageIO/imageio.h>

#include "core/atomic_file.h"

namespace wt {

namespace fs = std::filesystem;

namespace {

std::string lowercase_extension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

}  // namespace

ImageEncoding encoding_for_path(const std::string& path) {
    const std::string ext = lowercase_extension(path);
    if (ext == ".exr" || ext == ".hdr") return ImageEncoding::linear_float;
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg") return ImageEncoding::srgb_8bit;
    throw ImageError(path + ": unsupported image extension '" + ext + "' (use .exr, .hdr, .png, .jpg)");
}

void check_output_path(const std::string& path) {
    encoding_for_path(path);
    try {
        check_output_directory(path);
    } catch (const FileWriteError& e) {
        throw ImageError(e.what());
    }
}

float linear_to_srgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    if (c >= 1.0f) return 1.0f;  // the formula gives 1.055 - 0.055, which rounds just below 1
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

void write_image(const std::string& path, int width, int height, const std::vector<float>& rgb) {
    const ImageEncoding encoding = encoding_for_path(path);
    const OIIO::TypeDesc type = encoding == ImageEncoding::linear_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(width, height, 3, type);
    std::vector<uint8_t> bytes;
    const void* pixels = rgb.data();
    if (encoding == ImageEncoding::srgb_8bit) {
        bytes.resize(rgb.size());
        for (std::size_t i = 0; i < rgb.size(); ++i) bytes[i] = uint8_t(std::lround(255.0f * linear_to_srgb(rgb[i])));
        pixels = bytes.data();
        spec.attribute("oiio:ColorSpace", "sRGB");
    } else {
        spec.attribute("oiio:ColorSpace", "Linear");
    }
    try {
        write_file_atomically(path, [&](const std::string& temporary) {
            auto out = OIIO::ImageOutput::create(temporary);
            if (!out) throw ImageError(path + ": cannot create an image writer: " + OIIO::geterror());
            if (!(out->open(temporary, spec) && out->write_image(type, pixels) && out->close()))
                throw ImageError(path + ": writing failed: " + out->geterror());
        });
    } catch (const FileWriteError& e) {
        throw ImageError(e.what());
    }
}

}  // namespace wt
