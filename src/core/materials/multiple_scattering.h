#pragma once
// Kulla & Conty 2017 ("Revisiting Physically Based Shading at Imageworks", section on
// multiple scattering): a GGX reflection lobe keeps E(mu_o) of the light a perfect reflector
// would (ggx_albedo.h); the rest, 1 - E(mu_o), is what single scattering loses by ending every
// path that meets a second microfacet. They give it back as a second, diffuse-like lobe
//     f_ms(wo, wi) = F_ms (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)),
// symmetric in wo and wi (so light paths sample it as camera paths do) and reflecting exactly
// 1 - E(mu_o), since integral of (1 - E(mu_i)) mu_i dwi = pi (1 - E_avg). For colour, the
// energy that bounces k times is tinted k times: summing the series with the cosine-weighted
// average Fresnel F_avg = 2 integral F(mu) mu dmu gives
//     F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),
// which is 1 for a white metal (F = 1), so a rough white metal then reflects everything at every
// angle, and darker metals keep their saturation growing with roughness, as measured metals do.
// Local frame: z the macro normal, wo.z > 0.

#include <glm/vec3.hpp>

#include "core/materials/conductor_fresnel.h"
#include "core/materials/ggx_albedo.h"
#include "core/sampling/sampling.h"

namespace wt {

// F_avg of Schlick's term: 2 integral (F0 + (1 - F0)(1 - mu)^5) mu dmu = F0 + (1 - F0) / 21.
inline glm::vec3 schlick_fresnel_average(const glm::vec3& f0) { return f0 + (glm::vec3(1.0f) - f0) * (1.0f / 21.0f); }

// F_avg of a conductor's Fresnel term: Schlick's in closed form, the exact term by quadrature
// (the scene builder's, once per material: Material::conductor_fresnel_average).
glm::vec3 exact_fresnel_average(const ConductorFresnel& fresnel);

class MultipleScatteringLobe {
public:
    // No lobe: f is 0 (the single-scattering model).
    MultipleScatteringLobe() = default;

    // roughness perceptual (as the material gives it), fresnel_average the lobe's F_avg, cos_o
    // the view's mu_o.
    MultipleScatteringLobe(float roughness, const glm::vec3& fresnel_average, float cos_o)
        : table_(&ggx_albedo_table()), roughness_(roughness), single_albedo_(table_->albedo(cos_o, roughness)) {
        const float e_avg = table_->average(roughness);
        const float missing_average = 1.0f - e_avg;
        // A lobe that loses nothing on average (the smoothest roughness) has nothing to give back.
        if (!(missing_average > 1e-6f)) return;
        const glm::vec3 f_ms = fresnel_average * fresnel_average * e_avg / (glm::vec3(1.0f) - fresnel_average * missing_average);
        albedo_ = f_ms * (1.0f - single_albedo_);
        scale_ = albedo_ * (kInvPi / missing_average);
    }

    // f_ms(wo, wi), wi local; 0 below the surface.
    glm::vec3 f(const glm::vec3& wi) const {
        if (!(wi.z > 0.0f) || !table_) return glm::vec3(0.0f);
        return scale_ * (1.0f - table_->albedo(wi.z, roughness_));
    }

    // What it reflects of light arriving from wo: F_ms (1 - E(mu_o)).
    const glm::vec3& albedo() const { return albedo_; }
    // What the single-scattering lobe it completes keeps of it, with F = 1: E(mu_o).
    float single_albedo() const { return single_albedo_; }

private:
    const GgxAlbedoTable* table_ = nullptr;
    float roughness_ = 0.0f;
    float single_albedo_ = 1.0f;
    glm::vec3 albedo_{0.0f};
    glm::vec3 scale_{0.0f};  // F_ms (1 - E(mu_o)) / (pi (1 - E_avg)): f_ms over (1 - E(mu_i))
};

}  // namespace wt
