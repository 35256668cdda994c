#pragma once
// The interface between wavetrace and its image I/O module (libwavetrace_image_io.so, built from
// src/image_io_module/), which is the only code that links OpenImageIO. Debian's OpenImageIO
// pulls in some 260 shared libraries (OpenCV, ffmpeg, OpenVDB, ...), which cost every start of
// the program a quarter of a second and 130 MB before it did anything; loaded with dlopen on
// the first image read, or written in a format other than EXR and PNG (those two are written
// without it: direct_image_output.h), they cost only the runs that need them.
//
// Plain C types only, so that nothing but this header has to agree between the two sides, and
// no exception or allocator crosses it. Bump the version on any change.

#include <stddef.h>

extern "C" {

enum { WT_IMAGE_MODULE_ABI_VERSION = 2 };  // 2: read_image_source

enum WtPixelType { WT_PIXEL_FLOAT = 0, WT_PIXEL_UINT8 = 1 };
enum WtAttributeType { WT_ATTRIBUTE_STRING = 0, WT_ATTRIBUTE_INT = 1, WT_ATTRIBUTE_FLOAT = 2 };

struct WtImageAttribute {
    const char* name;
    int type;  // WtAttributeType: which of the values below is meant
    const char* string_value;
    int int_value;
    float float_value;
};

struct WtImageToWrite {
    const char* path;  // the file to create; its extension picks the format
    int width, height, channels;
    const char* const* channel_names;
    int pixel_type;     // WtPixelType
    const void* pixels; // width * height * channels values, interleaved, rows top to bottom
    const WtImageAttribute* attributes;
    int attribute_count;
};

// An image read by the module, in memory it allocated: hand it back to free_image.
struct WtReadImage {
    int width, height, channels;
    char** channel_names;
    float* pixels;  // converted to float (8-bit files: value / 255), interleaved, rows top to bottom
    int attribute_count;
    char** attribute_names;
    char** attribute_values;  // every attribute as text
};

// What read_image_source reads: the file at `name`, or, when `bytes` is set, the `size` bytes
// there (an image inside a .glb or a data URI; PNG or JPEG, told by their signature), with
// `name` for messages. An image of more than max_pixels pixels, or a side above max_side, is
// refused from its header, before its pixels are read (0: no limit).
struct WtImageSource {
    const char* name;
    const void* bytes;
    size_t size;
    size_t max_pixels;
    int max_side;
};

struct WtImageModuleApi {
    int abi_version;             // WT_IMAGE_MODULE_ABI_VERSION of the module's build
    const char* library_version; // OpenImageIO's, for messages
    // Each returns 0 on success; otherwise writes a NUL-terminated message (truncated to
    // error_size) naming the file. read_image leaves `image` empty on failure.
    int (*write_image)(const WtImageToWrite* image, char* error, size_t error_size);
    int (*read_image)(const char* path, WtReadImage* image, char* error, size_t error_size);
    void (*free_image)(WtReadImage* image);
    int (*read_image_source)(const WtImageSource* source, WtReadImage* image, char* error, size_t error_size);
};

// The module's one exported symbol.
#define WT_IMAGE_MODULE_ENTRY_POINT "wavetrace_image_module_api"
typedef const WtImageModuleApi* (*WtImageModuleEntryPoint)(void);

}  // extern "C"
