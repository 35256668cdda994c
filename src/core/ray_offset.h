#pragma once
// Where a spawned ray starts. A fixed epsilon is wrong at every scale but one: too small for
// a room a kilometre away from the origin (self-intersection acne), too large for a millimetre
// object (light leaks). Wachter & Binder, "A Fast and Robust Method for Avoiding
// Self-Intersection" (Ray Tracing Gems, ch. 6): move the point a fixed number of ulps along
// the normal, which scales with the point's magnitude, and a small absolute amount near the
// origin where ulps are tiny.

#include <cmath>
#include <cstdint>
#include <cstring>

#include <glm/vec3.hpp>

namespace wt {

namespace detail {
inline float offset_component(float p, float n) {
    constexpr float kNearOrigin = 1.0f / 32.0f;
    constexpr float kFloatScale = 1.0f / 65536.0f;
    constexpr float kIntScale = 256.0f;
    if (std::fabs(p) < kNearOrigin) return p + kFloatScale * n;
    int32_t bits;
    std::memcpy(&bits, &p, sizeof bits);
    const int32_t ulps = int32_t(kIntScale * n);
    bits += (p < 0.0f) ? -ulps : ulps;
    float out;
    std::memcpy(&out, &bits, sizeof out);
    return out;
}
}  // namespace detail

// n: unit normal pointing to the side the new ray leaves towards.
inline glm::vec3 offset_ray_origin(const glm::vec3& p, const glm::vec3& n) {
    return {detail::offset_component(p.x, n.x), detail::offset_component(p.y, n.y),
            detail::offset_component(p.z, n.z)};
}

}  // namespace wt
