#pragma once
// The Fresnel reflectance of a metal, per colour channel: Schlick's approximation from the
// reflectance at normal incidence F0 (what glTF's base colour of a metal is), or the exact
// Fresnel equations for a complex index of refraction eta + i k (measured data, e.g. from
// refractiveindex.info), unpolarised light, the outside medium of index 1.

#include <cmath>

#include <glm/vec3.hpp>

#include "core/base/float_minmax.h"

namespace wt {

// Schlick 1994 with F0 per channel: F0 + (1 - F0) (1 - cos)^5. With F0 = 1 exactly 1 at any
// angle (the (1 - F0) term vanishes), so such a conductor reflects like today's white mirror.
inline glm::vec3 schlick_conductor(const glm::vec3& f0, float cos_i) {
    const float m = fmax_float(0.0f, 1.0f - cos_i);
    const float m2 = m * m;
    return f0 + (glm::vec3(1.0f) - f0) * (m2 * m2 * m);
}

// The exact reflectance of one channel of a conductor (eta, k >= 0, eta > 0) at incidence
// cos_i in [0, 1]: the s and p amplitudes through a^2 + b^2 = |(eta + ik)^2 - sin^2|, the
// textbook form (Born & Wolf, sec. 14.2; written out as in Lagarde 2013, "Memo on Fresnel
// equations"). Grazing light (cos_i = 0) reflects fully; a 0/0 there (eta 1, k 0: no
// interface at grazing) is that limit too.
inline float fresnel_conductor_channel(float cos_i, float eta, float k) {
    const float cos2 = cos_i * cos_i;
    const float sin2 = fmax_float(0.0f, 1.0f - cos2);
    const float t0 = eta * eta - k * k - sin2;
    const float a2_plus_b2 = std::sqrt(t0 * t0 + 4.0f * eta * eta * k * k);
    const float a = std::sqrt(fmax_float(0.0f, 0.5f * (a2_plus_b2 + t0)));
    const float t1 = a2_plus_b2 + cos2;
    const float t2 = 2.0f * cos_i * a;
    if (!(t1 + t2 > 0.0f)) return 1.0f;
    const float rs = (t1 - t2) / (t1 + t2);
    const float t3 = cos2 * a2_plus_b2 + sin2 * sin2;
    const float t4 = t2 * sin2;
    const float rp = t3 + t4 > 0.0f ? rs * (t3 - t4) / (t3 + t4) : rs;
    return fmin_float(1.0f, fmax_float(0.0f, 0.5f * (rs + rp)));
}

inline glm::vec3 fresnel_conductor(float cos_i, const glm::vec3& eta, const glm::vec3& k) {
    return {fresnel_conductor_channel(cos_i, eta.x, k.x), fresnel_conductor_channel(cos_i, eta.y, k.y),
            fresnel_conductor_channel(cos_i, eta.z, k.z)};
}

// A conductor's Fresnel term as its material gives it: the complex index where one is given
// (eta.x > 0), else Schlick from F0.
struct ConductorFresnel {
    glm::vec3 f0{1.0f};
    glm::vec3 eta{0.0f}, k{0.0f};

    glm::vec3 operator()(float cos_i) const {
        return eta.x > 0.0f ? fresnel_conductor(cos_i, eta, k) : schlick_conductor(f0, cos_i);
    }
};

}  // namespace wt
