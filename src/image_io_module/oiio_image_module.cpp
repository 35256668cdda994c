// The image I/O module: OpenImageIO behind the plain C interface of image_module_abi.h. Built
// as its own shared object so that only a process that reads or writes an image loads
// OpenImageIO and the few hundred libraries Debian builds it with.

#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/image_io/image_module_abi.h"

namespace {

void set_error(char* error, size_t size, const std::string& message) {
    if (!error || size == 0) return;
    const size_t n = std::min(size - 1, message.size());
    std::memcpy(error, message.data(), n);
    error[n] = '\0';
}

char* copy_string(const std::string& s) {
    char* c = static_cast<char*>(std::malloc(s.size() + 1));
    if (!c) throw std::bad_alloc();
    std::memcpy(c, s.c_str(), s.size() + 1);
    return c;
}

int write_image(const WtImageToWrite* image, char* error, size_t error_size) {
    try {
        const OIIO::TypeDesc type = image->pixel_type == WT_PIXEL_UINT8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
        OIIO::ImageSpec spec(image->width, image->height, image->channels, type);
        spec.channelnames.assign(image->channel_names, image->channel_names + image->channels);
        spec.alpha_channel = -1;
        spec.z_channel = -1;
        for (int c = 0; c < image->channels; ++c)
            if (spec.channelnames[size_t(c)] == "Z") spec.z_channel = c;
        for (int i = 0; i < image->attribute_count; ++i) {
            const WtImageAttribute& a = image->attributes[i];
            if (a.type == WT_ATTRIBUTE_INT) spec.attribute(a.name, a.int_value);
            else if (a.type == WT_ATTRIBUTE_FLOAT) spec.attribute(a.name, a.float_value);
            else spec.attribute(a.name, a.string_value);
        }
        auto out = OIIO::ImageOutput::create(image->path);
        if (!out) {
            set_error(error, error_size, std::string(image->path) + ": cannot create an image writer: " + OIIO::geterror());
            return 1;
        }
        if (!(out->open(image->path, spec) && out->write_image(type, image->pixels) && out->close())) {
            set_error(error, error_size, std::string(image->path) + ": writing failed: " + out->geterror());
            return 1;
        }
        return 0;
    } catch (const std::exception& e) {
        set_error(error, error_size, std::string(image->path) + ": writing failed: " + e.what());
        return 1;
    }
}

void free_image(WtReadImage* image) {
    if (!image) return;
    for (int c = 0; c < image->channels && image->channel_names; ++c) std::free(image->channel_names[c]);
    for (int i = 0; i < image->attribute_count; ++i) {
        if (image->attribute_names) std::free(image->attribute_names[i]);
        if (image->attribute_values) std::free(image->attribute_values[i]);
    }
    std::free(image->channel_names);
    std::free(image->attribute_names);
    std::free(image->attribute_values);
    std::free(image->pixels);
    *image = WtReadImage{};
}

// The file or bytes' format, for OpenImageIO to pick its reader by: PNG and JPEG by signature.
std::string name_for_reader(const WtImageSource& source) {
    if (!source.bytes) return source.name;
    const auto* b = static_cast<const unsigned char*>(source.bytes);
    if (source.size >= 8 && std::memcmp(b, "\x89PNG\r\n\x1a\n", 8) == 0) return "image.png";
    if (source.size >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return "image.jpg";
    return {};
}

// The fewest bytes a PNG of width x height pixels can be. Its pixel rows (a filter byte and at
// least one bit per pixel each) are one deflate stream, which expands at most 1032-fold (zlib's
// technical details: a 258-byte match coded in about two bits). A smaller file is truncated or
// damaged, and is refused before its pixels are allocated, however many it claims.
size_t least_png_bytes(int width, int height) {
    return size_t(height) * (1 + (size_t(width) + 7) / 8) / 1032;
}

// The size of what is read: the bytes given, or the file's.
size_t source_bytes(const WtImageSource& source) {
    if (source.bytes) return source.size;
    std::error_code ec;
    const auto size = std::filesystem::file_size(source.name, ec);
    return ec ? 0 : size_t(size);
}

int read_image_source(const WtImageSource* source, WtReadImage* image, char* error, size_t error_size) {
    *image = WtReadImage{};
    const std::string path = source->name;
    try {
        const std::string reader_name = name_for_reader(*source);
        if (reader_name.empty()) {
            set_error(error, error_size, path + ": not a PNG or JPEG image (its first bytes are neither signature)");
            return 1;
        }
        OIIO::Filesystem::IOMemReader memory(source->bytes, source->bytes ? source->size : 0);
        // The texels as the file stores them. OpenImageIO associates (premultiplies) the colour of
        // PNG, TGA and TIFF files with their alpha unless told not to, but those formats store it
        // unassociated, and glTF 2.0's base colour (3.9.2) and MTL's maps mean it so: a leaf's
        // green would darken towards its cut-out edges, where alpha falls. EXR stores associated
        // colour, which this leaves as it is.
        // (With a configuration, OpenImageIO 2.4 reads bytes in memory only if it names them too.)
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        OIIO::Filesystem::IOProxy* proxy = source->bytes ? &memory : nullptr;
        if (proxy) config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        auto in = OIIO::ImageInput::open(reader_name, &config, proxy);
        if (!in) {
            set_error(error, error_size, path + ": cannot read the image: " + OIIO::geterror());
            return 1;
        }
        const OIIO::ImageSpec& spec = in->spec();
        const bool too_wide = source->max_side > 0 && (spec.width > source->max_side || spec.height > source->max_side);
        if (too_wide || (source->max_pixels > 0 && size_t(spec.width) * size_t(spec.height) > source->max_pixels)) {
            set_error(error, error_size,
                      path + ": " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                          " pixels, more than the " + std::to_string(source->max_side) + " per side and " +
                          std::to_string(source->max_pixels) + " in all an image may have here");
            return 1;
        }
        if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
            set_error(error, error_size, path + ": the image is empty");
            return 1;
        }
        if (std::strcmp(in->format_name(), "png") == 0) {
            const size_t size = source_bytes(*source), least = least_png_bytes(spec.width, spec.height);
            if (size < least) {
                set_error(error, error_size,
                          path + ": " + std::to_string(size) + " bytes cannot hold " + std::to_string(spec.width) + " x " +
                              std::to_string(spec.height) + " PNG pixels (at least " + std::to_string(least) +
                              "): the file is truncated or damaged");
                return 1;
            }
        }
        const size_t values = size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels);
        image->pixels = static_cast<float*>(std::malloc(std::max<size_t>(1, values) * sizeof(float)));
        image->channel_names = static_cast<char**>(std::calloc(size_t(std::max(1, spec.nchannels)), sizeof(char*)));
        const size_t attributes = spec.extra_attribs.size();
        image->attribute_names = static_cast<char**>(std::calloc(std::max<size_t>(1, attributes), sizeof(char*)));
        image->attribute_values = static_cast<char**>(std::calloc(std::max<size_t>(1, attributes), sizeof(char*)));
        if (!image->pixels || !image->channel_names || !image->attribute_names || !image->attribute_values)
            throw std::bad_alloc();
        image->width = spec.width, image->height = spec.height, image->channels = spec.nchannels;
        for (int c = 0; c < spec.nchannels; ++c) image->channel_names[c] = copy_string(spec.channel_name(c));
        for (const OIIO::ParamValue& p : spec.extra_attribs) {
            image->attribute_names[image->attribute_count] = copy_string(p.name().string());
            image->attribute_values[image->attribute_count++] = copy_string(p.get_string());
        }
        if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image->pixels)) {
            set_error(error, error_size, path + ": reading failed: " + in->geterror());
            free_image(image);
            return 1;
        }
        return 0;
    } catch (const std::exception& e) {
        set_error(error, error_size, path + ": reading failed: " + e.what());
        free_image(image);
        return 1;
    }
}

int read_image(const char* path, WtReadImage* image, char* error, size_t error_size) {
    const WtImageSource file{path, nullptr, 0, 0, 0};
    return read_image_source(&file, image, error, error_size);
}

const WtImageModuleApi api = {WT_IMAGE_MODULE_ABI_VERSION, OIIO_VERSION_STRING, write_image, read_image, free_image,
                              read_image_source};

}  // namespace

extern "C" __attribute__((visibility("default"))) const WtImageModuleApi* wavetrace_image_module_api() { return &api; }
