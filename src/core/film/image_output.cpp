#include "core/film/image_output.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>

#include <OpenImageIO/imageio.h>

namespace wt {

namespace fs = std::filesystem;

namespace {

std::string lowercase_extension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// Keeps the extension last, since OpenImageIO picks the writer from it.
std::string temporary_path_for(const std::string& path) {
    const fs::path p(path);
    const std::string name = "." + p.stem().string() + ".tmp-" + std::to_string(getpid()) + p.extension().string();
    return (p.parent_path() / name).string();
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
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw ImageError(path + ": directory '" + dir.string() + "' does not exist");
    if (access(dir.c_str(), W_OK) != 0) throw ImageError(path + ": directory '" + dir.string() + "' is not writable");
    // Found after rendering, these cost the whole render: rename() cannot replace a directory,
    // and the temporary name is longer than the image's.
    if (fs::is_directory(path, ec)) throw ImageError(path + ": is a directory, cannot be replaced by an image");
    const long name_max = pathconf(dir.c_str(), _PC_NAME_MAX);
    const std::size_t limit = name_max > 0 ? std::size_t(name_max) : 255;
    const std::size_t temporary_name = fs::path(temporary_path_for(path)).filename().string().size();
    if (temporary_name > limit)
        throw ImageError(path + ": file name too long: the temporary file written beside it would have a " +
                         std::to_string(temporary_name) + "-byte name, more than the " + std::to_string(limit) +
                         " the directory allows");
}

float linear_to_srgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    if (c >= 1.0f) return 1.0f;  // the formula gives 1.055 - 0.055, which rounds just below 1
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

void write_image(const std::string& path, int width, int height, const std::vector<float>& rgb) {
    const ImageEncoding encoding = encoding_for_path(path);
    const std::string temporary = temporary_path_for(path);
    auto out = OIIO::ImageOutput::create(temporary);
    if (!out) throw ImageError(path + ": cannot create an image writer: " + OIIO::geterror());

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

    const bool ok = out->open(temporary, spec) && out->write_image(type, pixels) && out->close();
    if (!ok) {
        const std::string why = out->geterror();
        out.reset();
        std::remove(temporary.c_str());
        throw ImageError(path + ": writing failed: " + why);
    }
    out.reset();
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec) {
        std::remove(temporary.c_str());
        throw ImageError(path + ": cannot move the finished image into place: " + ec.message());
    }
}

}  // namespace wt
