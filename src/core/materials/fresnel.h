#pragma once
// Smooth-dielectric optics: Snell's law and Schlick's approximation to the Fresnel reflectance.

#include <cmath>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/base/accuracy.h"
#include "core/base/float_minmax.h"

namespace wt {

// Schlick 1994. cos_outside is the cosine of the angle on the optically thinner side: the
// incident angle when entering the glass, the transmitted angle when leaving it. Using the
// inside angle on exit would get total internal reflection's onset wrong.
//
// An index-matched interface (ior 1) reflects nothing at any angle; Schlick's (1 - cos)^5 term
// assumes a contrast and would still reflect 38% at 80 degrees, drawing a dark ring around a
// sphere that should be invisible (tests/extremes_test.cpp), so that case is exact here.
inline float schlick_reflectance(float cos_outside, float ior) {
    if (ior == 1.0f) return 0.0f;
    float r0 = (1.0f - ior) / (1.0f + ior);
    r0 *= r0;
    const float m = 1.0f - cos_outside;
    const float m2 = m * m;
    return r0 + (1.0f - r0) * (m2 * m2 * m);
}

// The Fresnel equations for a smooth dielectric, unpolarised light: the mean of the s and p
// reflectances. eta = n_incident / n_transmitted; cos_i and cos_t are the cosines on each side
// (from refract()). Exact where Schlick is an approximation (off by up to ~1.5% absolute
// around 60-80 degrees for IOR 1.5).
inline float fresnel_dielectric(float cos_i, float cos_t, float eta) {
    const float rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (rs * rs + rp * rp);
}

// Refracts unit direction d through a surface whose unit normal n faces against d
// (dot(d, n) < 0). eta = n_incident / n_transmitted. Empty on total internal reflection.
struct Refraction {
    glm::vec3 direction;
    float cos_transmitted;
};
inline std::optional<Refraction> refract(const glm::vec3& d, const glm::vec3& n, float eta) {
    const float cos_i = -glm::dot(d, n);
    const float sin2_t = eta * eta * fmax_float(0.0f, 1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) return std::nullopt;
    const float cos_t = std::sqrt(1.0f - sin2_t);
    return Refraction{glm::normalize(eta * d + (eta * cos_i - cos_t) * n), cos_t};
}

inline glm::vec3 reflect(const glm::vec3& d, const glm::vec3& n) { return d - 2.0f * glm::dot(d, n) * n; }

// Smooth glass's reflectance at an interface of unit normal n (facing against d) for light
// arriving along d, given what refract(d, n, eta) made of it: 1 on total internal reflection,
// else by the Fresnel model. `front`: d arrives from the outside of the glass (index 1).
// Shared by the smooth glass (n the surface's normal) and the rough one (n a microfacet's).
inline float glass_reflectance(const glm::vec3& d, const glm::vec3& n, const std::optional<Refraction>& refracted, bool front,
                               float ior, float eta, FresnelModel fresnel) {
    if (!refracted) return 1.0f;
    const float cos_i = -glm::dot(d, n);
    const float cos_outside = front ? cos_i : refracted->cos_transmitted;
    return fresnel == FresnelModel::exact ? fresnel_dielectric(cos_i, refracted->cos_transmitted, eta)
                                          : schlick_reflectance(cos_outside, ior);
}

}  // namespace wt
