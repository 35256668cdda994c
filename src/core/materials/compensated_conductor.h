#pragma once
// A rough metal that keeps the energy single scattering loses: the rough conductor's GGX lobe
// (rough_conductor.h) plus Kulla & Conty's multiple-scattering lobe (multiple_scattering.h),
//     f = f_single + f_ms,
// sampled as one mixture (ggx_cosine_mixture.h) that picks the GGX lobe in proportion to its
// share of the albedo. Symmetric in wo and wi, as both lobes are. With F = 1 (a white metal) it
// reflects all it receives at every angle and roughness, within the albedo table's error.
// Local frame: z the macro normal, wo.z > 0.

#include <glm/vec3.hpp>

#include "core/materials/conductor_fresnel.h"
#include "core/materials/ggx.h"
#include "core/materials/ggx_cosine_mixture.h"
#include "core/materials/microfacet_sample.h"
#include "core/materials/multiple_scattering.h"
#include "core/materials/rough_conductor.h"

namespace wt {

class CompensatedConductor {
public:
    // roughness perceptual; fresnel_average the Fresnel term's F_avg (schlick_fresnel_average,
    // or Material::conductor_fresnel_average for a complex index); wo the view, local.
    CompensatedConductor(float roughness, const ConductorFresnel& fresnel, const glm::vec3& fresnel_average,
                         const glm::vec3& wo)
        : single_(ggx_alpha(roughness), fresnel),
          multiple_(roughness, fresnel_average, wo.z),
          ggx_probability_(ggx_probability(fresnel_average, multiple_)) {}

    glm::vec3 f(const glm::vec3& wo, const glm::vec3& wi) const { return single_.f(wo, wi) + multiple_.f(wi); }

    float pdf(const glm::vec3& wo, const glm::vec3& wi) const { return lobes().pdf(wo, wi); }

    MicrofacetSample sample(const glm::vec3& wo, float u0, float u1, float u_choice) const {
        return lobes().sample(wo, u0, u1, u_choice, [this](const glm::vec3& o, const glm::vec3& i) { return f(o, i); });
    }

private:
    GgxCosineMixture lobes() const { return GgxCosineMixture(single_, ggx_probability_); }

    // The GGX lobe's albedo, about F_avg E(mu_o), against the multiple-scattering lobe's
    // F_ms (1 - E(mu_o)), averaged over the channels; 1 where the second reflects nothing.
    static float ggx_probability(const glm::vec3& fresnel_average, const MultipleScatteringLobe& multiple) {
        const float single = (fresnel_average.x + fresnel_average.y + fresnel_average.z) * (1.0f / 3.0f) * multiple.single_albedo();
        const glm::vec3& m = multiple.albedo();
        const float rest = (m.x + m.y + m.z) * (1.0f / 3.0f);
        return rest > 0.0f && single + rest > 0.0f ? single / (single + rest) : 1.0f;
    }

    RoughConductor single_;
    MultipleScatteringLobe multiple_;
    float ggx_probability_;
};

}  // namespace wt
