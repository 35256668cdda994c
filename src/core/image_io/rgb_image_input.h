#pragma once
// Reads an image file (through the image I/O module, core/image_io/image_input.h) into linear
// RGB, for comparing a render against a reference. EXR/HDR (and any float format) are taken as linear radiance; an 8-bit image marked
// sRGB (our PNGs) is decoded through the sRGB curve, so a PNG compares against an EXR on the same
// scale (to 8 bits). A one-channel image is grey (R = G = B); with more than three channels the
// first three are RGB (R, G and B by name when the file has them).

#include <string>

#include "core/image_io/image_error.h"
#include "core/image_io/rgb_image.h"

namespace wt {

// Throws ImageError naming the path: missing or unreadable file, two channels, a NaN or infinite
// pixel (with its coordinates).
RgbImage read_rgb_image(const std::string& path);

float srgb_to_linear(float encoded);

}  // namespace wt
