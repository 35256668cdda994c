#pragma once
// Where a spawned ray starts. A fixed epsilon is wrong at every scale but one: too small for
// a room a kilometre from the origin (self-intersection acne), too large for a millimetre
// object (light leaks), so the offset here is derived from a bound on the rounding error of
// the hit point itself, as in pbrt-v4 (Pharr, Jakob & Humphreys, 4th ed., sec. 6.8): the
// point moves along the normal just past the slab of points it may really be, and each
// component is then rounded one more ulp away from the surface.
//
// Wachter & Binder's fixed 256-ulp offset (Ray Tracing Gems ch. 6) was tried first: with the
// hexroom moved 1e5 from the origin it is 2 m, and rays refracted into the glass spheres
// started on their far side (tests/scale_test.cpp).

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace wt {

// Higham's gamma_n = n u / (1 - n u), u = 2^-24: the relative error bound of n roundings.
constexpr float rounding_gamma(int n) {
    constexpr float u = 0.5f * std::numeric_limits<float>::epsilon();
    return float(n) * u / (1.0f - float(n) * u);
}

// |v| per component, as one and-mask each. glm::abs is `x >= 0 ? x : -x`, which g++ turns into
// a compare and a branch per component, on the path of every spawned and shadow ray. (The two
// differ only in the sign they give -0, which no bound here cares about.)
inline glm::vec3 magnitude(const glm::vec3& v) { return {std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}; }

// Error bound of v0 + u e1 + v e2 computed in float with e1 = v1 - v0, e2 = v2 - v0 rounded.
inline glm::vec3 triangle_point_error(const glm::vec3& v0, const glm::vec3& e1, const glm::vec3& e2, float u, float v) {
    return rounding_gamma(7) * (magnitude(v0) + magnitude(u * e1) + magnitude(v * e2));
}

// The same bound from |v0|, |e1|, |e2| computed beforehand, for barycentrics u, v >= 0: rounding
// is symmetric, so |u * e1| == u * |e1| exactly and the result is the same bits.
inline glm::vec3 triangle_point_error_from_magnitudes(const glm::vec3& abs_v0, const glm::vec3& abs_e1, const glm::vec3& abs_e2,
                                                      float u, float v) {
    return rounding_gamma(7) * (abs_v0 + u * abs_e1 + v * abs_e2);
}

// Error bound of c + r * normalize(...), the hit point reprojected onto its sphere.
inline glm::vec3 sphere_point_error(const glm::vec3& center, float radius, const glm::vec3& unit_normal) {
    return rounding_gamma(5) * (magnitude(center) + magnitude(radius * unit_normal));
}

// The next float towards +inf / -inf, inline: std::nextafter is a libm call, and this runs
// six times per shadow ray.
inline float next_float_up(float v) {
    if (std::isinf(v) && v > 0.0f) return v;
    if (v == -0.0f) v = 0.0f;
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    bits = v >= 0.0f ? bits + 1 : bits - 1;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}
inline float next_float_down(float v) { return -next_float_up(-v); }

// p: the computed point, error: a per-component bound on |p - exact point|, n: unit normal
// pointing to the side the new ray leaves towards.
inline glm::vec3 offset_ray_origin(const glm::vec3& p, const glm::vec3& error, const glm::vec3& n) {
    const float distance = glm::dot(magnitude(n), error);
    const glm::vec3 offset = distance * n;
    glm::vec3 out = p + offset;
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0f) out[i] = next_float_up(out[i]);
        else if (offset[i] < 0.0f) out[i] = next_float_down(out[i]);
    }
    return out;
}

// A triangle hit point's error bound as the watertight test needs it: no component below a
// quarter of the largest. A point on an axis-aligned plane through 0 (a wall on x = 0) has error
// 0 along its normal, every coordinate there being exact, so the offset above leaves the ray on
// its own plane. Moller-Trumbore then computes t = 0 exactly and rejects the plane, but the
// watertight test computes t from the sheared vertices, whose rounding is at the scale of the
// other coordinates: many such rays came out at a t of a few ulps and hit the wall they left, and
// a room with walls on x = 0 and z = 0 rendered too dark. Only scenes with that test pay for it.
inline glm::vec3 with_watertight_floor(const glm::vec3& error) {
    const float larger_xy = error.x > error.y ? error.x : error.y;  // maxss, no branch
    const float floor = 0.25f * (larger_xy > error.z ? larger_xy : error.z);
    return {error.x > floor ? error.x : floor, error.y > floor ? error.y : floor, error.z > floor ? error.z : floor};
}

// For a point computed in a few operations from values no larger than itself (error ~ |p|).
inline glm::vec3 offset_ray_origin(const glm::vec3& p, const glm::vec3& n) {
    return offset_ray_origin(p, rounding_gamma(7) * magnitude(p), n);
}

}  // namespace wt
