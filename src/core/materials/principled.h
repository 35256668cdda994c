#pragma once
// glTF 2.0's metallic-roughness material (the specification's appendix B, "BRDF
// implementation"), as a BRDF in the local frame (z the macro normal, wo.z > 0):
//     material        = mix(dielectric_brdf, metal_brdf, metallic)
//     dielectric_brdf = fresnel_mix(ior, base = Lambert(baseColor), layer = specular_brdf(alpha))
//     metal_brdf      = conductor_fresnel(f0 = baseColor, specular_brdf(alpha))
// with alpha = roughness^2 (ggx.h), specular_brdf the GGX lobe with the height-correlated
// Smith term, and both Fresnel terms Schlick's at wo.h (h the half vector). Expanded, with
// F_d the dielectric's Schlick term from F0_d = ((ior - 1) / (ior + 1))^2 and F_m the metal's:
//     f = (1 - metallic) (1 - F_d(wo.h)) baseColor / pi
//       + ((1 - metallic) F_d(wo.h) + metallic F_m(wo.h)) D G2 / (4 cos_o cos_i).
// Schlick's term is linear in F0, so the specular factor is Schlick's with F0 =
// mix(F0_d, baseColor, metallic): the lobe is the rough conductor's (rough_conductor.h) with
// that F0, its f, pdf and sampler reused as they are. An ior of 1 gives F0_d = 0, and Schlick's
// grazing term then still reflects, as the specification's formula does.
//
// Symmetric in wo and wi (the half vector, D, G2 and the cosines all are), so light paths
// sample it as camera paths do. The specification's coupling of the two lobes is not energy
// conserving: seen at grazing angles the diffuse lobe keeps its (1 - F_d(wo.h)), which is near
// 1 for most wi, while the specular lobe's Fresnel term climbs towards 1, and the directional
// albedo of a white plastic rises past 1 (about 1.3 at roughness 0.3 seen at 87 degrees;
// tests/principled_bsdf_test.cpp measures it); for smooth surfaces the excess starts past
// about 45 degrees. Seen within 40 degrees of the normal it stays at or below 1. Renderers that
// conserve energy there (Cycles' Principled BSDF) scale the diffuse by the specular lobe's albedo
// instead (Kulla & Conty 2017); not done here. With multiple_scattering the specular lobe gets
// back what its single scattering loses (multiple_scattering.h), as a metal's does; the
// coupling above is the specification's either way.
//
// Sampling picks one lobe, the specular with probability P from the lobes' Fresnel weights at
// the macro normal, else the cosine lobe, with the one-sample mixture pdf (ggx_cosine_mixture.h).

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/base/float_minmax.h"
#include "core/materials/conductor_fresnel.h"
#include "core/materials/ggx.h"
#include "core/materials/ggx_cosine_mixture.h"
#include "core/materials/microfacet_sample.h"
#include "core/materials/multiple_scattering.h"
#include "core/materials/rough_conductor.h"
#include "core/sampling/sampling.h"

namespace wt {

// The dielectric's reflectance at normal incidence for an ior (1.5 gives glTF's 0.04).
inline float dielectric_f0(float ior) {
    const float r = (ior - 1.0f) / (ior + 1.0f);
    return r * r;
}

class PrincipledBrdf {
public:
    // base_color and metallic in [0, 1] (a metallic 1 usually loads as the conductor instead:
    // microfacet_material.h); roughness perceptual; wo the view, local, for the lobe choice.
    // multiple_scattering: the specular lobe gets Kulla & Conty's compensation
    // (multiple_scattering.h), with the F_avg of its Schlick term, and the cosine lobe, which
    // samples the diffuse, samples that too.
    PrincipledBrdf(const glm::vec3& base_color, float metallic, float roughness, float ior, const glm::vec3& wo,
                   bool multiple_scattering = false)
        : specular_(ggx_alpha(roughness), ConductorFresnel{specular_f0(base_color, metallic, ior)}),
          multiple_(multiple_scattering ? MultipleScatteringLobe(roughness, schlick_fresnel_average(specular_f0(base_color, metallic, ior)), wo.z)
                                        : MultipleScatteringLobe()),
          diffuse_((1.0f - metallic) * kInvPi * base_color),
          f0_dielectric_(dielectric_f0(ior)),
          specular_probability_(specular_probability(base_color, metallic, f0_dielectric_, wo, multiple_.albedo())) {}

    glm::vec3 f(const glm::vec3& wo, const glm::vec3& wi) const {
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return glm::vec3(0.0f);
        const glm::vec3 sum = wo + wi;
        const float length2 = glm::dot(sum, sum);
        if (!(length2 > 0.0f)) return glm::vec3(0.0f);
        const float wo_h = fmin_float(1.0f, glm::dot(wo, sum) / std::sqrt(length2));
        const float transmitted = 1.0f - schlick_conductor(glm::vec3(f0_dielectric_), wo_h).x;
        return specular_.f(wo, wi) + multiple_.f(wi) + diffuse_ * transmitted;
    }

    float pdf(const glm::vec3& wo, const glm::vec3& wi) const { return lobes().pdf(wo, wi); }

    // u_choice picks the lobe, (u0, u1) the direction within it.
    MicrofacetSample sample(const glm::vec3& wo, float u0, float u1, float u_choice) const {
        return lobes().sample(wo, u0, u1, u_choice, [this](const glm::vec3& o, const glm::vec3& i) { return f(o, i); });
    }

    float specular_probability() const { return specular_probability_; }

private:
    GgxCosineMixture lobes() const { return GgxCosineMixture(specular_, specular_probability_); }

    // The specular lobe's F0: Schlick's term is linear in F0, so mixing the dielectric's and the
    // metal's terms by metallic is one term of the mixed F0.
    static glm::vec3 specular_f0(const glm::vec3& base_color, float metallic, float ior) {
        return glm::vec3((1.0f - metallic) * dielectric_f0(ior)) + metallic * base_color;
    }

    // The specular lobe's share of what the lobes reflect seen from wo, by their Fresnel weights
    // at the macro normal (the lobes' albedos without the microfacet terms), averaged over the
    // channels; the multiple-scattering lobe's albedo counts with the diffuse, since the cosine
    // lobe samples both. Positive whenever metallic < 1 (Schlick's grazing term is, and F0_d is
    // for any ior but 1); 1 with nothing else to sample (a black base).
    static float specular_probability(const glm::vec3& base_color, float metallic, float f0_dielectric, const glm::vec3& wo,
                                      const glm::vec3& multiple_albedo) {
        const float grazing = schlick_conductor(glm::vec3(0.0f), fmin_float(1.0f, fmax_float(0.0f, wo.z))).x;
        const float base = (base_color.x + base_color.y + base_color.z) * (1.0f / 3.0f);
        const float f_d = f0_dielectric + (1.0f - f0_dielectric) * grazing;
        const float specular = (1.0f - metallic) * f_d + metallic * (base + (1.0f - base) * grazing);
        const float diffuse = (1.0f - metallic) * (1.0f - f_d) * base +
                              (multiple_albedo.x + multiple_albedo.y + multiple_albedo.z) * (1.0f / 3.0f);
        return specular + diffuse > 0.0f ? specular / (specular + diffuse) : 1.0f;
    }

    RoughConductor specular_;
    MultipleScatteringLobe multiple_;  // none without multiple_scattering
    glm::vec3 diffuse_;    // (1 - metallic) baseColor / pi
    float f0_dielectric_;  // declared before specular_probability_, which reads it
    float specular_probability_;
};

}  // namespace wt
