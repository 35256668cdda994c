#pragma once
// Reads an image file (any format OpenImageIO reads: EXR with all its layers, PNG, HDR, ...)
// through the image I/O module, for tests, error metrics against references, and tools.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/image_io/image_error.h"

namespace wt {

struct ImageData {
    int width = 0, height = 0;
    std::vector<std::string> channels;  // as the file names them: "R", "G", "B", "albedo.R", "Z", ...
    std::vector<float> pixels;          // width * height * channels.size(), interleaved, rows top to bottom;
                                        // 8-bit files as value / 255
    std::vector<std::pair<std::string, std::string>> attributes;  // the file's metadata, every value as text

    // Index of a channel, or -1.
    int channel_index(const std::string& name) const;
    // The channel's value at pixel (x, y). Throws ImageError if the channel is missing.
    float value(const std::string& channel, int x, int y) const;
    // All of the channel's values, rows top to bottom. Throws ImageError if it is missing.
    std::vector<float> channel(const std::string& name) const;
    std::optional<std::string> attribute(const std::string& name) const;
};

// Throws ImageError naming the file if it cannot be read (or the module cannot be loaded).
ImageData read_image(const std::string& path);

// Bounds an image is held to from its header, before its pixels are read (0: none).
struct ImageLimits {
    std::size_t max_pixels = 0;
    int max_side = 0;
};
ImageData read_image(const std::string& path, ImageLimits limits);
// A PNG or JPEG image in memory (inside a .glb, a data URI); `name` says which in messages.
ImageData read_image_bytes(const std::string& name, const void* bytes, std::size_t size, ImageLimits limits);

}  // namespace wt
