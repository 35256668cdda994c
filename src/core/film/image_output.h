#pragma once
// Writes the resolved film: EXR and PNG files through OpenEXR and libpng
// (core/image_io/direct_image_output.h), the others through the image I/O module (OpenImageIO,
// loaded on first use: core/image_io/image_module_abi.h). The format follows the extension: .exr and .hdr keep
// linear float radiance; .png and .jpg get the sRGB transfer curve, clamped to 8 bits. EXR
// files also hold the AOV layers, if any; the others hold the beauty image only. The image
// goes to a temporary file beside the target and is renamed over it, so an interrupted or
// failed write never leaves a half-written image under the requested name.

#include <cstdint>
#include <string>
#include <vector>

#include "core/film/image_channels.h"
#include "core/image_io/image_error.h"

namespace wt {

enum class ImageEncoding { linear_float, srgb_8bit };

// Throws ImageError naming the path if the extension is not one we write.
ImageEncoding encoding_for_path(const std::string& path);

// Whether images written to `path` hold AOV layers (EXR does; the others hold RGB only).
bool holds_layers(const std::string& path);

// Checked before rendering, so a typo in -o costs nothing: extension known, directory exists
// and is writable, the path is not a directory, and the temporary file's name (longer than
// the image's) fits the directory's name limit.
void check_output_path(const std::string& path);

// Also before rendering: if `path`'s format is written through the image I/O module, the module
// loads (throws ImageError saying why not).
void check_image_writer_available(const std::string& path);

// What every image records of how it was made. In EXR files as the attributes
// `wavetrace:spp` (int), `wavetrace:seed` (string: it is 64-bit), `wavetrace:scene_hash`,
// `wavetrace:render_seconds` (float), `wavetrace:version`; in PNG files as text chunks of the
// same names; in all formats but HDR (whose writer has no place for it) as `Software` and a
// one-line `ImageDescription`.
struct ImageMetadata {
    uint32_t spp = 0;
    uint64_t seed = 0;
    std::string scene_hash;  // hash_to_hex(scene_content_hash(...))
    double render_seconds = 0.0;
    std::string program_version;
};

// rgb: width * height * 3 linear floats, rows top to bottom. `layers`: extra channels written
// after R, G, B in EXR files (AOVs), ignored by the other formats.
void write_image(const std::string& path, int width, int height, const std::vector<float>& rgb,
                 const ImageMetadata* metadata = nullptr, const ImageChannels* layers = nullptr);

float linear_to_srgb(float linear);

}  // namespace wt
