// PNG files through libpng, written as OpenImageIO's PNG writer writes them (see
// direct_image_output.h for why not through it): 8 bits a channel, zlib's default compression,
// an sRGB image marked by the sRGB chunk with its gAMA and cHRM fallbacks (a linear one by a
// gAMA of 1), and every attribute as an uncompressed text chunk under its name, but
// `ImageDescription`, which is PNG's registered keyword `Description`.

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/image_io/direct_image_output.h"

namespace wt {

namespace {

// libpng reports an error by calling this, which must not return: it keeps the message and
// jumps back to the setjmp in write_rows.
struct PngErrorState {
    char message[256] = "";
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
    auto* state = static_cast<PngErrorState*>(png_get_error_ptr(png));
    std::snprintf(state->message, sizeof state->message, "%s", message ? message : "libpng error");
    png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

std::string text_of(const WtImageAttribute& a) {
    if (a.type == WT_ATTRIBUTE_INT) return std::to_string(a.int_value);
    if (a.type == WT_ATTRIBUTE_FLOAT) {
        char text[32];
        std::snprintf(text, sizeof text, "%.9g", double(a.float_value));
        return text;
    }
    return a.string_value ? a.string_value : "";
}

int colour_type(int channels) {
    switch (channels) {
    case 1: return PNG_COLOR_TYPE_GRAY;
    case 2: return PNG_COLOR_TYPE_GRAY_ALPHA;
    case 3: return PNG_COLOR_TYPE_RGB;
    default: return PNG_COLOR_TYPE_RGB_ALPHA;
    }
}

// Everything libpng is handed, made before the setjmp: a longjmp must not skip a destructor.
struct PngContent {
    std::vector<std::string> keys, values;
    std::vector<png_text> texts;
    std::vector<png_bytep> rows;
    bool srgb = false, linear = false;
};

PngContent content_of(const WtImageToWrite& image) {
    PngContent c;
    for (int i = 0; i < image.attribute_count; ++i) {
        const WtImageAttribute& a = image.attributes[i];
        const std::string name = a.name;
        const std::string value = text_of(a);
        if (name == "oiio:ColorSpace") {
            c.srgb = value == "sRGB";
            c.linear = value == "Linear";
        }
        c.keys.push_back(name == "ImageDescription" ? "Description" : name.substr(0, 79));  // PNG's longest keyword
        c.values.push_back(value);
    }
    for (std::size_t i = 0; i < c.keys.size(); ++i) {
        png_text t{};
        t.compression = PNG_TEXT_COMPRESSION_NONE;
        t.key = c.keys[i].data();
        t.text = c.values[i].data();
        t.text_length = c.values[i].size();
        c.texts.push_back(t);
    }
    auto* pixels = static_cast<png_bytep>(const_cast<void*>(image.pixels));
    const std::size_t row_bytes = std::size_t(image.width) * std::size_t(image.channels);
    for (int y = 0; y < image.height; ++y) c.rows.push_back(pixels + std::size_t(y) * row_bytes);
    return c;
}

// Writes the image to `file`; false (the message in `errors`) if libpng failed.
bool write_rows(std::FILE* file, const WtImageToWrite& image, PngContent& content, PngErrorState& errors) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, on_png_error, on_png_warning);
    if (!png) {
        std::snprintf(errors.message, sizeof errors.message, "out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    bool written = false;
    if (info && setjmp(png_jmpbuf(png)) == 0) {
        png_init_io(png, file);
        png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8, colour_type(image.channels),
                     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        if (content.srgb) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
        if (content.linear) png_set_gAMA(png, info, 1.0);
        if (!content.texts.empty()) png_set_text(png, info, content.texts.data(), int(content.texts.size()));
        png_write_info(png, info);
        png_write_image(png, content.rows.data());
        png_write_end(png, nullptr);
        written = true;
    } else if (!info) {
        std::snprintf(errors.message, sizeof errors.message, "out of memory");
    }
    png_destroy_write_struct(&png, &info);
    return written;
}

}  // namespace

void write_png(const WtImageToWrite& image) {
    const std::string path = image.path;
    if (image.pixel_type != WT_PIXEL_UINT8 || image.channels < 1 || image.channels > 4)
        throw ImageError(path + ": PNG files are written from 8-bit pixels of 1 to 4 channels");
    PngContent content = content_of(image);
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw ImageError(path + ": cannot create: " + std::strerror(errno));
    PngErrorState errors;
    const bool written = write_rows(file, image, content, errors);
    const bool closed = std::fclose(file) == 0;  // the last bytes reach the disk here
    if (!written) throw ImageError(path + ": writing failed: " + errors.message);
    if (!closed) throw ImageError(path + ": writing failed: " + std::strerror(errno));
}

}  // namespace wt
