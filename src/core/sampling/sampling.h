#pragma once
// Warps from the unit square to the domains the integrators sample, with their pdfs.

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/base/float_minmax.h"
#include "core/sampling/quarter_pi_trig.h"

namespace wt {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kInvPi = 0.31830988618379067154f;

// Tangent frame around a unit normal without the division by (1 + n.z) blowing up near
// n.z = -1: Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017).
struct Frame {
    glm::vec3 tangent, bitangent, normal;

    explicit Frame(const glm::vec3& n) : normal(n) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        tangent = glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
        bitangent = glm::vec3(b, sign + n.y * n.y * a, -n.y);
    }
    glm::vec3 to_world(const glm::vec3& local) const {
        return local.x * tangent + local.y * bitangent + local.z * normal;
    }
};

// Shirley & Chiu's concentric map: keeps strata of the square compact on the disk, so the
// stratified pixel and light samples stay stratified after warping.
// The angle is pi/4 * (b/a), or pi/2 - pi/4 * (a/b), whose cos and sin are the sin and cos
// of pi/4 * (a/b): either way only the octant [-pi/4, pi/4] is evaluated.
inline glm::vec2 sample_concentric_disk(float u0, float u1) {
    const float a = 2.0f * u0 - 1.0f;
    const float b = 2.0f * u1 - 1.0f;
    if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f};
    if (std::abs(a) > std::abs(b)) {
        const SinCos t = sin_cos_quarter_pi((kPi / 4.0f) * (b / a));
        return {a * t.cos, a * t.sin};
    }
    const SinCos t = sin_cos_quarter_pi((kPi / 4.0f) * (a / b));
    return {b * t.sin, b * t.cos};
}

// Malley's method: project the disk up to the hemisphere; pdf = cos(theta) / pi.
// Local frame, z is the normal. z is kept strictly positive so the pdf never is zero.
inline glm::vec3 sample_cosine_hemisphere(float u0, float u1) {
    const glm::vec2 d = sample_concentric_disk(u0, u1);
    const float z = std::sqrt(fmax_float(1e-12f, 1.0f - d.x * d.x - d.y * d.y));
    return {d.x, d.y, z};
}

inline float cosine_hemisphere_pdf(float cos_theta) { return cos_theta > 0.0f ? cos_theta * kInvPi : 0.0f; }

// Uniform unit vector within angle theta_max of +z (local frame), given 1 - cos(theta_max) (2:
// the whole sphere); pdf 1 / (2 pi (1 - cos theta_max)). 1 - cos rather than cos: exact for
// the narrow cone of a sun.
inline glm::vec3 sample_uniform_cone(float u0, float u1, float one_minus_cos_max) {
    const float one_minus_cos = u0 * one_minus_cos_max;
    const float cos_theta = 1.0f - one_minus_cos;
    const float sin_theta = std::sqrt(fmax_float(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
    const float phi = 2.0f * kPi * u1;
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

// Uniform point on a triangle as barycentrics (b1, b2) of v1 and v2; pdf = 1 / area.
inline glm::vec2 sample_uniform_triangle(float u0, float u1) {
    const float su0 = std::sqrt(u0);
    return {u1 * su0, 1.0f - su0};
}

}  // namespace wt
