#pragma once
// A sampler's wrap modes (glTF's wrapS / wrapT: REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT) as maps
// from texture coordinates and texel indices into the image.

#include <cmath>
#include <cstdint>

namespace wt {

enum class TextureWrap : uint8_t { repeat, clamp, mirror };

// A coordinate (in units of the image's extent) brought into a bounded range the wrap mode maps
// identically, before it is scaled to texels: a uv of 1e9 or NaN must not overflow the texel
// index. repeat: [0, 1); mirror: [0, 2) (one period of the reflection); clamp: [-1, 2]. NaN: 0.
inline float wrap_coordinate(float u, TextureWrap wrap) {
    if (!std::isfinite(u)) return 0.0f;
    switch (wrap) {
        case TextureWrap::repeat: return u - std::floor(u);
        case TextureWrap::mirror: return u - 2.0f * std::floor(0.5f * u);
        case TextureWrap::clamp: break;
    }
    return u < -1.0f ? -1.0f : (u > 2.0f ? 2.0f : u);
}

// A texel index i (any integer a bilinear footprint of a wrapped coordinate reaches) into [0, n).
inline int wrap_texel(int i, int n, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::repeat: return ((i % n) + n) % n;
        case TextureWrap::mirror: {
            const int m = ((i % (2 * n)) + 2 * n) % (2 * n);
            return m < n ? m : 2 * n - 1 - m;
        }
        case TextureWrap::clamp: break;
    }
    return i < 0 ? 0 : (i >= n ? n - 1 : i);
}

}  // namespace wt
