#pragma once
// Filtered lookups into a MipPyramid: bilinear between the four texels about a point of a level
// (texel centres at (i + 0.5) / width, so a lookup at a centre returns that texel exactly), and
// linear between the two levels about a fractional level of detail.

#include <cmath>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/textures/mip_pyramid.h"

namespace wt {

inline glm::vec4 bilinear(const MipLevel& level, TextureWrap wrap_s, TextureWrap wrap_t, glm::vec2 uv) {
    const float x = wrap_coordinate(uv.x, wrap_s) * float(level.width) - 0.5f;
    const float y = wrap_coordinate(uv.y, wrap_t) * float(level.height) - 0.5f;
    const float x0f = std::floor(x), y0f = std::floor(y);
    const float fx = x - x0f, fy = y - y0f;
    const int x0 = int(x0f), y0 = int(y0f);
    const int xa = wrap_texel(x0, level.width, wrap_s), xb = wrap_texel(x0 + 1, level.width, wrap_s);
    const int ya = wrap_texel(y0, level.height, wrap_t), yb = wrap_texel(y0 + 1, level.height, wrap_t);
    const glm::vec4 top = level.at(xa, ya) + fx * (level.at(xb, ya) - level.at(xa, ya));
    const glm::vec4 bottom = level.at(xa, yb) + fx * (level.at(xb, yb) - level.at(xa, yb));
    return top + fy * (bottom - top);
}

// lod: the level of detail (0 = the image, 1 = half its size, ...), clamped to the pyramid;
// NaN (an undefined footprint) reads level 0.
inline glm::vec4 texture_lookup(const MipPyramid& texture, glm::vec2 uv, float lod) {
    const float top = float(texture.level_count() - 1);
    if (!(lod > 0.0f)) return bilinear(texture.level(0), texture.wrap_s(), texture.wrap_t(), uv);
    if (lod >= top) return bilinear(texture.level(texture.level_count() - 1), texture.wrap_s(), texture.wrap_t(), uv);
    const float lower = std::floor(lod);
    const std::size_t l = std::size_t(lower);
    const glm::vec4 a = bilinear(texture.level(l), texture.wrap_s(), texture.wrap_t(), uv);
    const glm::vec4 b = bilinear(texture.level(l + 1), texture.wrap_s(), texture.wrap_t(), uv);
    return a + (lod - lower) * (b - a);
}

}  // namespace wt
