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
// Whether a colour texture file's values are sRGB-encoded: all but the float formats, EXR and
// HDR (by the extension, any case), whose values are linear already.
bool colour_file_is_srgb(const std::string& path);
std::shared_ptr<const TextureTexels> read_texture_bytes(const std::string& name, const void* bytes, std::size_t size);

}  // namespace wt
