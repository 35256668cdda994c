#pragma once
// A texture as the scene description holds it: the file's texels (RGBA, as read: 8-bit values
// / 255), whether they are colour (sRGB-encoded, decoded to linear when the scene is built) or
// data (roughness, metallic, normals: used as stored), and the sampler's wrap modes.
// Plain data, filled by the loaders; core/textures/mip_pyramid.h is what the renderer reads.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/textures/texture_wrap.h"

namespace wt {

struct TextureTexels {
    int width = 0, height = 0;
    std::vector<glm::vec4> rgba;  // width * height, rows top to bottom (v = 0 is the top row, as in glTF)
};

struct TextureImage {
    std::string name;  // the file (or "scene.glb: image 2"), for messages and the texture memory line
    // Shared: a glTF image used by two textures (two samplers, or colour and data) is read once.
    std::shared_ptr<const TextureTexels> texels;
    bool srgb = true;  // colour: RGB decoded from sRGB (alpha is always linear)
    TextureWrap wrap_s = TextureWrap::repeat, wrap_t = TextureWrap::repeat;
    // KHR_texture_transform: uv' = translate(offset) rotate(rotation) scale(scale) uv, the
    // rotation (radians) turning (1, 0) towards (0, -1) as the extension defines it.
    glm::vec2 offset{0.0f}, scale{1.0f};
    float rotation = 0.0f;
    // Which coordinates it reads: 0 (glTF's TEXCOORD_0, OBJ's vt) or 1 (TEXCOORD_1, where a
    // textureInfo's texCoord, or KHR_texture_transform's, says so).
    int coordinate_set = 0;
};

}  // namespace wt
