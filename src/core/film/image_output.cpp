#include "core/film/image_output.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "core/system/atomic_file.h"
#include "core/image_io/direct_image_output.h"
#include "core/image_io/image_module.h"

namespace wt {

namespace fs = std::filesystem;

namespace {

std::string lowercase_extension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// The attributes of the metadata, kept alive (the strings) for the module's call.
struct Attributes {
    std::vector<std::string> strings;
    std::vector<WtImageAttribute> list;

    void add_string(const char* name, std::string value) {
        strings.push_back(std::move(value));
        list.push_back({name, WT_ATTRIBUTE_STRING, nullptr, 0, 0.0f});
    }
    void add(const char* name, int value) { list.push_back({name, WT_ATTRIBUTE_INT, nullptr, value, 0.0f}); }
    void add(const char* name, float value) { list.push_back({name, WT_ATTRIBUTE_FLOAT, nullptr, 0, value}); }
    // Pointers into `strings` are taken only once it has stopped growing.
    const WtImageAttribute* finish() {
        std::size_t s = 0;
        for (WtImageAttribute& a : list)
            if (a.type == WT_ATTRIBUTE_STRING) a.string_value = strings[s++].c_str();
        return list.data();
    }
};

Attributes image_attributes(const std::string& ext, const ImageMetadata& m, ImageEncoding encoding) {
    Attributes a;
    a.add_string("oiio:ColorSpace", encoding == ImageEncoding::srgb_8bit ? "sRGB" : "Linear");
    if (ext == ".hdr") return a;  // OpenImageIO's Radiance writer keeps none of the rest
    std::ostringstream seconds;
    seconds.precision(6);
    seconds << m.render_seconds;
    const std::string program = "wavetrace " + m.program_version;
    a.add_string("Software", program);
    a.add_string("ImageDescription", program + ": " + std::to_string(m.spp) + " spp, seed " + std::to_string(m.seed) +
                                         ", scene hash " + m.scene_hash + ", rendered in " + seconds.str() + " s");
    if (ext == ".exr") {
        // Typed where the type fits; the seed is 64-bit, which EXR's int attribute is not.
        a.add("wavetrace:spp", int(m.spp));
        a.add_string("wavetrace:seed", std::to_string(m.seed));
        a.add_string("wavetrace:scene_hash", m.scene_hash);
        a.add("wavetrace:render_seconds", float(m.render_seconds));
        a.add_string("wavetrace:version", m.program_version);
    } else if (ext == ".png") {
        // OpenImageIO writes string attributes as PNG text chunks under their names.
        a.add_string("wavetrace:spp", std::to_string(m.spp));
        a.add_string("wavetrace:seed", std::to_string(m.seed));
        a.add_string("wavetrace:scene_hash", m.scene_hash);
        a.add_string("wavetrace:render_seconds", seconds.str());
        a.add_string("wavetrace:version", m.program_version);
    }
    return a;
}

}  // namespace

ImageEncoding encoding_for_path(const std::string& path) {
    const std::string ext = lowercase_extension(path);
    if (ext == ".exr" || ext == ".hdr") return ImageEncoding::linear_float;
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg") return ImageEncoding::srgb_8bit;
    throw ImageError(path + ": unsupported image extension '" + ext + "' (use .exr, .hdr, .png, .jpg)");
}

bool holds_layers(const std::string& path) { return lowercase_extension(path) == ".exr"; }

void check_output_path(const std::string& path) {
    encoding_for_path(path);
    try {
        check_output_directory(path);
    } catch (const FileWriteError& e) {
        throw ImageError(e.what());
    }
}

// EXR and PNG are written here (direct_image_output.h); the other formats through the module.
bool written_by_module(const std::string& ext) { return ext != ".exr" && ext != ".png"; }

void check_image_writer_available(const std::string& path) {
    if (written_by_module(lowercase_extension(path))) image_module();
}

float linear_to_srgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    if (c >= 1.0f) return 1.0f;  // the formula gives 1.055 - 0.055, which rounds just below 1
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

void write_image(const std::string& path, int width, int height, const std::vector<float>& rgb,
                 const ImageMetadata* metadata, const ImageChannels* layers) {
    const ImageEncoding encoding = encoding_for_path(path);
    const std::string ext = lowercase_extension(path);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    if (rgb.size() != 3 * pixels) throw ImageError(path + ": " + std::to_string(rgb.size()) + " values for a " +
                                                   std::to_string(width) + "x" + std::to_string(height) + " RGB image");
    const bool with_layers = layers && !layers->names.empty() && holds_layers(path);
    if (with_layers && layers->values.size() != pixels * layers->names.size())
        throw ImageError(path + ": the AOV layers do not match the image's size");

    std::vector<std::string> names = {"R", "G", "B"};
    std::vector<uint8_t> bytes;
    std::vector<float> floats;
    const void* data = rgb.data();
    if (encoding == ImageEncoding::srgb_8bit) {
        bytes.resize(rgb.size());
        for (std::size_t i = 0; i < rgb.size(); ++i) bytes[i] = uint8_t(std::lround(255.0f * linear_to_srgb(rgb[i])));
        data = bytes.data();
    } else if (with_layers) {
        const std::size_t extra = layers->names.size();
        names.insert(names.end(), layers->names.begin(), layers->names.end());
        floats.resize(pixels * names.size());
        for (std::size_t p = 0; p < pixels; ++p) {
            float* out = &floats[p * names.size()];
            std::copy_n(&rgb[3 * p], 3, out);
            std::copy_n(&layers->values[p * extra], extra, out + 3);
        }
        data = floats.data();
    }
    std::vector<const char*> name_pointers;
    for (const std::string& n : names) name_pointers.push_back(n.c_str());
    Attributes attributes = metadata ? image_attributes(ext, *metadata, encoding) : Attributes{};
    if (!metadata) attributes.add_string("oiio:ColorSpace", encoding == ImageEncoding::srgb_8bit ? "sRGB" : "Linear");
    const WtImageAttribute* attribute_list = attributes.finish();

    const WtImageModuleApi* module = written_by_module(ext) ? &image_module() : nullptr;
    try {
        write_file_atomically(path, [&](const std::string& temporary) {
            const WtImageToWrite image{temporary.c_str(), width, height, int(names.size()), name_pointers.data(),
                                       encoding == ImageEncoding::srgb_8bit ? WT_PIXEL_UINT8 : WT_PIXEL_FLOAT, data,
                                       attribute_list, int(attributes.list.size())};
            if (module) {
                char error[1024];
                if (module->write_image(&image, error, sizeof error) != 0) throw ImageError(path + ": " + error);
                return;
            }
            try {
                if (ext == ".exr") write_exr(image);
                else write_png(image);
            } catch (const ImageError& e) {  // it names the temporary file; say which image that was
                throw ImageError(path + ": " + e.what());
            }
        });
    } catch (const FileWriteError& e) {
        throw ImageError(e.what());
    }
}

}  // namespace wt
