#pragma once
// What a node of the light tree knows about the emitters below it, and how much they may matter
// to a shading point (Conty Estevez & Kulla 2018, "Importance Sampling of Many Lights with
// Adaptive Tree Splitting", sec. 4; pbrt-v4's LightBounds): a box that holds them, their total
// power, and a cone of normals (axis, half-angle theta_o). Every emitter here is a one-sided
// triangle, so its emission half-angle theta_e is pi/2 about each normal and is not stored.
// LightBounds is what the tree is built from; CompactLightBounds what its descent reads.

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace wt {

struct LightBounds {
    glm::vec3 lo{INFINITY}, hi{-INFINITY};
    float power = 0.0f;        // pi * area * luminance, summed
    glm::vec3 axis{0.0f, 0.0f, 1.0f};
    float cos_theta_o = 1.0f;  // -1: normals in every direction

    glm::vec3 centre() const { return 0.5f * (lo + hi); }
    float surface_area() const {
        const glm::vec3 d = hi - lo;
        return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
};

// What the light tree's descent reads of a node (pbrt-v4's CompactLightBounds, unquantised):
// the box as its bounding sphere, and the cone's sine beside its cosine, so that one importance
// costs one division and four square roots.
struct CompactLightBounds {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
    glm::vec3 axis{0.0f, 0.0f, 1.0f};
    float radius2 = 0.0f;  // radius * radius
    float cos_theta_o = 1.0f, sin_theta_o = 0.0f;
    float power = 0.0f;

    CompactLightBounds() = default;
    explicit CompactLightBounds(const LightBounds& b)
        : centre(b.centre()),
          radius(0.5f * glm::length(b.hi - b.lo)),
          axis(b.axis),
          radius2(radius * radius),
          cos_theta_o(b.cos_theta_o),
          sin_theta_o(std::sqrt(std::max(0.0f, 1.0f - b.cos_theta_o * b.cos_theta_o))),
          power(b.power) {}

    // An upper bound, up to the distance clamp, on what the emitters can send to a surface at `p`
    // of normal `n`: power times the largest cosine at which any normal in the cone can face any
    // point of the box seen from p, times the largest |cosine| between n and a direction from p
    // into the box (both sides: a rough glass vertex receives from behind too), over the squared
    // distance to the box's centre (the paper's eq. 3; pbrt-v4's LightBounds::Importance). Zero
    // only when no emitter in the box can face p, so no emitter that could light p is ever given
    // probability zero.
    float importance(const glm::vec3& p, const glm::vec3& n) const {
        const glm::vec3 to_p = p - centre;
        const float d2 = glm::dot(to_p, to_p);
        // Inside the box's bounding sphere every direction may face p: the cosine bounds are 1,
        // and the distance no less than the sphere's radius (pbrt-v4 clamps likewise) so a light
        // near p does not take every sample.
        if (d2 <= radius2) return power / std::max(radius2, 1e-30f);
        const float inverse_d = 1.0f / std::sqrt(d2);
        // theta_w: the angle between the cone's axis and the direction from the centre to p;
        // theta_b: the half-angle the bounding sphere subtends at p.
        const float cos_w = glm::dot(axis, to_p) * inverse_d;
        const float sin_b = radius * inverse_d;
        const float cos_b = std::sqrt(std::max(0.0f, 1.0f - sin_b * sin_b));
        // theta' = max(0, theta_w - theta_o - theta_b), as cosines: cos(a - b), 1 where a <= b.
        float cos_x = 1.0f, sin_x = 0.0f;
        if (cos_w < cos_theta_o) {
            const float sin_w = std::sqrt(std::max(0.0f, 1.0f - cos_w * cos_w));
            cos_x = cos_w * cos_theta_o + sin_w * sin_theta_o;
            sin_x = sin_w * cos_theta_o - cos_w * sin_theta_o;
        }
        const float cos_p = cos_x < cos_b ? cos_x * cos_b + sin_x * sin_b : 1.0f;
        if (!(cos_p > 0.0f)) return 0.0f;  // theta' >= theta_e = pi/2: every emitter faces away
        // The receiver: theta_i between n and the direction to the centre, less theta_b.
        const float cos_i = std::fabs(glm::dot(n, to_p)) * inverse_d;
        float cos_ip = 1.0f;
        if (cos_i < cos_b) cos_ip = cos_i * cos_b + std::sqrt(std::max(0.0f, 1.0f - cos_i * cos_i)) * sin_b;
        return power * cos_p * cos_ip * (inverse_d * inverse_d);
    }
};

// The smallest cone holding both (pbrt-v4's DirectionCone Union): the half-angle spans a's
// cone, the angle between the axes and b's, and the axis turns from a's towards b's.
inline void unite_cones(glm::vec3& axis, float& cos_theta, const glm::vec3& b_axis, float b_cos_theta) {
    const double theta_a = std::acos(std::clamp(double(cos_theta), -1.0, 1.0));
    const double theta_b = std::acos(std::clamp(double(b_cos_theta), -1.0, 1.0));
    const double theta_d = std::acos(std::clamp(double(glm::dot(axis, b_axis)), -1.0, 1.0));
    constexpr double kPiD = 3.14159265358979323846;
    if (std::min(theta_d + theta_b, kPiD) <= theta_a) return;
    if (std::min(theta_d + theta_a, kPiD) <= theta_b) {
        axis = b_axis, cos_theta = b_cos_theta;
        return;
    }
    const double theta_o = 0.5 * (theta_a + theta_d + theta_b);
    const glm::dvec3 a(axis), b(b_axis);
    const glm::dvec3 w = glm::cross(a, b);
    const double w_length = glm::length(w);
    if (theta_o >= kPiD || !(w_length > 0.0)) {
        cos_theta = -1.0f;
        return;
    }
    // Rotate a by theta_o - theta_a about a x b (Rodrigues), towards b.
    const glm::dvec3 k = w / w_length;
    const double turn = theta_o - theta_a;
    const glm::dvec3 r = a * std::cos(turn) + glm::cross(k, a) * std::sin(turn) + k * glm::dot(k, a) * (1.0 - std::cos(turn));
    axis = glm::vec3(glm::normalize(r));
    cos_theta = float(std::cos(theta_o));
}

inline LightBounds unite(const LightBounds& a, const LightBounds& b) {
    if (a.lo.x > a.hi.x) return b;  // a is empty
    LightBounds u = a;
    u.lo = glm::min(a.lo, b.lo);
    u.hi = glm::max(a.hi, b.hi);
    u.power = a.power + b.power;
    unite_cones(u.axis, u.cos_theta_o, b.axis, b.cos_theta_o);
    return u;
}

}  // namespace wt
