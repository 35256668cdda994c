#pragma once
// Texture images read through the image module (OpenImageIO): files (PNG, JPEG, EXR, HDR, ...)
// and PNG/JPEG bytes in memory (inside a .glb, data URIs). Throws ImageError naming the file.

#include <cstddef>
#include <memory>
#include <string>

#include "core/image_io/image_input.h"
#include "core/textures/texture_image.h"

namespace wt {

// Refused from the header, before any pixel is read: a 16384^2 image's pyramid of float RGBA
// would take 5.7 GB. 8192^2 (1.4 GB) is the most a texture may have, however it is shaped.
constexpr int kMaxTextureSide = 16384;
constexpr std::size_t kMaxTexturePixels = std::size_t(8192) * 8192;

// An image's channels as RGBA: one is grey, two grey and alpha, three RGB, four or more RGBA
// (the first four); a missing alpha is 1.
std::shared_ptr<const TextureTexels> texels_of(const ImageData& image);

std::shared_ptr<const TextureTexels> read_texture_file(const std::string& path);
// Which of an image's channels a scalar map (MTL's map_d, map_Pr, map_Pm) takes its value from:
// one the file names (MTL's -imfchan r, g, b, l), or, for coverage (map_d), its alpha where it
// has an alpha channel (exporters that reuse the colour image for map_d mean that) and its
// luminance where not. Luminance is the grey value, or Rec. 709's weights of the stored RGB: the
// channel the MTL specification reads from scalar maps by default (-imfchan l), as in the grey
// masks of Crytek's Sponza.
enum class ScalarChannel { red, green, blue, alpha, luminance, alpha_else_luminance };

// A scalar map as texels whose four channels all hold its value (the alpha test reads the
// fourth, a metallic-roughness texture is assembled from the first).
std::shared_ptr<const TextureTexels> read_scalar_texture_file(const std::string& path, ScalarChannel channel);
// Whether a colour texture file's values are sRGB-encoded: all but the float formats, EXR and
// HDR (by the extension, any case), whose values are linear already.
bool colour_file_is_srgb(const std::string& path);
std::shared_ptr<const TextureTexels> read_texture_bytes(const std::string& name, const void* bytes, std::size_t size);

}  // namespace wt
