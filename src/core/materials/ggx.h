#pragma once
// The Trowbridge-Reitz (GGX) microfacet distribution, isotropic, with the height-correlated
// Smith masking-shadowing term and sampling of the visible normals. Everything is in the local
// frame of the macro surface: z is its normal, and directions are unit vectors. The BSDFs built
// on it are rough_conductor.h and rough_dielectric.h.
//
// - D (Trowbridge & Reitz 1975; Walter et al. 2007, eq. 33):
//     D(h) = alpha^2 / (pi (cos^2 (alpha^2 - 1) + 1)^2).
// - Smith's Lambda for GGX (Heitz 2014, "Understanding the Masking-Shadowing Function in
//   Microfacet-Based BRDFs", eq. 72): Lambda(w) = (sqrt(1 + alpha^2 tan^2) - 1) / 2, written as
//   (sqrt(cos^2 + alpha^2 sin^2) / |cos| - 1) / 2 so that normal incidence needs no tangent.
// - G2, height-correlated (Heitz 2014, eq. 99): 1 / (1 + Lambda(wo) + Lambda(wi)). For
//   transmission Heitz gives a Beta-function form; like pbrt-v4 we use the same expression,
//   which is exact for reflection and agrees with it to within a few percent for refraction.
// - Visible normals (Heitz 2018, "Sampling the GGX Distribution of Visible Normals") are drawn
//   with Dupuy & Benyoub 2023, "Sampling Visible GGX Normals with Spherical Caps": in the
//   configuration stretched to alpha = 1 the visible normals of a direction wo are the points
//   of a spherical cap of the unit sphere shifted by wo, so one uniform point of the cap gives
//   one visible normal, with no polar/azimuth split and no branch. The pdf of h is
//   D_wo(h) = G1(wo) max(0, wo.h) D(h) / wo.z (Heitz 2018, eq. 1).

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/base/float_minmax.h"
#include "core/sampling/sampling.h"

namespace wt {

// The smallest alpha a rough lobe uses. Below it the lobe is narrower than float can aim a
// direction: the half vector of two unit vectors is off by about 1e-4 rad after rounding, and
// D changes by (1 + (1e-4 / alpha)^2)^2 across that error, 2% at alpha 1e-3 but a factor of 4
// at 1e-4; D's peak, 1 / (pi alpha^2), also grows without bound. pbrt-v4 switches to its
// specular code at the same alpha. Roughness exactly 0 never gets here: it is the smooth
// mirror or glass (microfacet_material.h).
constexpr float kMinGgxAlpha = 1e-3f;

// Perceptual roughness to the distribution's alpha, as glTF 2.0 (appendix B) defines it.
inline float ggx_alpha(float roughness) { return fmax_float(kMinGgxAlpha, roughness * roughness); }

class GgxDistribution {
public:
    explicit GgxDistribution(float alpha) : alpha_(alpha), alpha2_(alpha * alpha) {}

    float alpha() const { return alpha_; }

    // Microfacet normal density per unit solid angle, times cos: integrates D(h) h.z to 1.
    float d(const glm::vec3& h) const {
        const float cos2 = h.z * h.z;
        if (!(h.z > 0.0f)) return 0.0f;
        const float t = cos2 * (alpha2_ - 1.0f) + 1.0f;
        return alpha2_ / (kPi * t * t);
    }

    // Smith's Lambda for GGX; infinite (everything masked) exactly at the horizon.
    float lambda(const glm::vec3& w) const {
        const float cos2 = w.z * w.z;
        if (!(cos2 > 0.0f)) return INFINITY;
        const float sin2 = fmax_float(0.0f, 1.0f - cos2);
        return 0.5f * (std::sqrt(cos2 + alpha2_ * sin2) / std::abs(w.z) - 1.0f);
    }

    // Masking of one direction: 1 / (1 + Lambda).
    float g1(const glm::vec3& w) const { return 1.0f / (1.0f + lambda(w)); }

    // Height-correlated masking-shadowing of the pair.
    float g2(const glm::vec3& wo, const glm::vec3& wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }

    // The density of visible normals h seen from wo (wo.z > 0), per unit solid angle of h.
    float visible_normal_pdf(const glm::vec3& wo, const glm::vec3& h) const {
        const float wo_h = glm::dot(wo, h);
        if (!(wo_h > 0.0f) || !(wo.z > 0.0f)) return 0.0f;
        return g1(wo) * wo_h * d(h) / wo.z;
    }

    // A visible normal of wo (wo.z >= 0), Dupuy & Benyoub 2023, listing 3: stretch wo to the
    // alpha = 1 configuration, take the uniform point (u0, u1) of the cap of the unit sphere
    // above -wo.z, add wo and unstretch. Always a unit vector with h.z >= 0.
    glm::vec3 sample_visible_normal(const glm::vec3& wo, float u0, float u1) const {
        const glm::vec3 stretched = glm::normalize(glm::vec3(alpha_ * wo.x, alpha_ * wo.y, wo.z));
        const float phi = 2.0f * kPi * u0;
        const float z = (1.0f - u1) * (1.0f + stretched.z) - stretched.z;
        const float sin_theta = std::sqrt(fmax_float(0.0f, 1.0f - z * z));
        const glm::vec3 cap_point(sin_theta * std::cos(phi), sin_theta * std::sin(phi), z);
        const glm::vec3 h = cap_point + stretched;
        const glm::vec3 unstretched(alpha_ * h.x, alpha_ * h.y, fmax_float(0.0f, h.z));
        const float length2 = glm::dot(unstretched, unstretched);
        // The cap point opposite to wo itself (a set of measure zero): the macro normal.
        if (!(length2 > 0.0f)) return glm::vec3(0.0f, 0.0f, 1.0f);
        return unstretched / std::sqrt(length2);
    }

private:
    float alpha_, alpha2_;
};

// Coordinates of world direction w in the frame f (z along f.normal).
inline glm::vec3 to_local(const Frame& f, const glm::vec3& w) {
    return {glm::dot(w, f.tangent), glm::dot(w, f.bitangent), glm::dot(w, f.normal)};
}

}  // namespace wt
