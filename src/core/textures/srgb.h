#pragma once
// The sRGB transfer function's inverse (IEC 61966-2-1): what a colour texture's stored values
// (8-bit PNG/JPEG, as glTF requires for baseColor and emissive) mean as linear reflectance.

#include <cmath>

namespace wt {

inline float srgb_to_linear(float c) {
    if (c <= 0.04045f) return c / 12.92f;
    return std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace wt
