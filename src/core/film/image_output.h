#pragma once
// Writes the resolved film through OpenImageIO. The format follows the extension: .exr and
// .hdr keep linear float radiance; .png and .jpg get the sRGB transfer curve, clamped to 8
// bits. The image goes to a temporary file beside the target and is renamed over it, so an
// interrupted or failed write never leaves a half-written image under the requested name.

#include <stdexcept>
#include <string>
#include <vector>

namespace wt {

struct ImageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

enum class ImageEncoding { linear_float, srgb_8bit };

// Throws ImageError naming the path if the extension is not one we write.
ImageEncoding encoding_for_path(const std::string& path);

// Checked before rendering, so a typo in -o costs nothing: extension known, directory exists
// and is writable, the path is not a directory, and the temporary file's name (longer than
// the image's) fits the directory's name limit.
void check_output_path(const std::string& path);

// rgb: width * height * 3 linear floats, rows top to bottom.
void write_image(const std::string& path, int width, int height, const std::vector<float>& rgb);

float linear_to_srgb(float linear);

}  // namespace wt
