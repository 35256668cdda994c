#pragma once
// What the BSDF tests share: materials built in one line, directions from angles, and the
// directional albedo by quadrature.

#include <cmath>

#include "core/materials/bsdf.h"

namespace wt::test {

inline Material diffuse(MaterialType type, float albedo, float sigma = 0.0f) {
    Material m;
    m.type = type;
    m.albedo = glm::vec3(albedo);
    m.sigma = sigma;
    return m;
}

// glTF's metallic-roughness material itself, whatever metallic (principled_material would load
// metallic 1 without emission as the conductor).
inline Material principled(const glm::vec3& base, float metallic, float roughness, float ior = 1.5f,
                           const glm::vec3& emission = glm::vec3(0.0f)) {
    Material m;
    m.name = "principled";
    m.type = MaterialType::principled;
    m.base_color = base;
    m.metallic = metallic;
    m.roughness = roughness;
    m.ior = ior;
    m.emission = emission;
    return m;
}

// Unit direction at polar angle theta from +z and azimuth phi.
inline glm::vec3 direction_at(double theta, double phi) {
    return glm::vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
}

// Directional albedo, the integral of f * cos over the hemisphere around +z, by n x n midpoint
// quadrature in (cos^2 theta, phi), where the cosine-weighted measure is uniform:
// f cos dw = f * pi * d(cos^2 theta) d(phi) / (2 pi).
inline double directional_albedo(const Material& m, const glm::vec3& wo, int n) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double cos2 = (i + 0.5) / n;
            const glm::vec3 wi = direction_at(std::acos(std::sqrt(cos2)), 2.0 * M_PI * (j + 0.5) / n);
            sum += double(eval_diffuse_bsdf(m, glm::vec3(0, 0, 1), wo, wi).x) * M_PI;
        }
    }
    return sum / (double(n) * n);
}

}  // namespace wt::test
