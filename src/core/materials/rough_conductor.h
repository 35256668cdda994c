#pragma once
// A rough metal: GGX microfacets reflecting with a conductor's Fresnel term (Walter et al. 2007,
// "Microfacet Models for Refraction through Rough Surfaces", eq. 20, with Heitz 2014's
// height-correlated G2):
//     f(wo, wi) = F(wo.h) D(h) G2(wo, wi) / (4 cos_o cos_i),  h = normalize(wo + wi).
// It is symmetric in wo and wi, so light paths sample and evaluate it as camera paths do.
// Single scattering only: light that bounces between microfacets more than once is lost, up to
// about 40% of it at roughness 1 (Kulla & Conty 2017 would compensate; not done yet).
// Local frame: z the macro normal, wo.z > 0.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/materials/conductor_fresnel.h"
#include "core/materials/ggx.h"
#include "core/materials/microfacet_sample.h"

namespace wt {

class RoughConductor {
public:
    RoughConductor(float alpha, const ConductorFresnel& fresnel) : ggx_(alpha), fresnel_(fresnel) {}

    glm::vec3 f(const glm::vec3& wo, const glm::vec3& wi) const {
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return glm::vec3(0.0f);
        const glm::vec3 sum = wo + wi;
        const float length2 = glm::dot(sum, sum);
        if (!(length2 > 0.0f)) return glm::vec3(0.0f);
        const glm::vec3 h = sum / std::sqrt(length2);
        return fresnel_(fmin_float(1.0f, glm::dot(wo, h))) * (ggx_.d(h) * ggx_.g2(wo, wi) / (4.0f * wo.z * wi.z));
    }

    // The reflected visible normal's pdf: D_wo(h) times the reflection's Jacobian 1 / (4 wo.h).
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const {
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
        const glm::vec3 sum = wo + wi;
        const float length2 = glm::dot(sum, sum);
        if (!(length2 > 0.0f)) return 0.0f;
        const glm::vec3 h = sum / std::sqrt(length2);
        return ggx_.g1(wo) * ggx_.d(h) / (4.0f * wo.z);
    }

    // A visible normal, reflected: weight F G2 / G1(wo), as f cos / pdf simplifies to.
    MicrofacetSample sample(const glm::vec3& wo, float u0, float u1) const {
        MicrofacetSample s;
        const glm::vec3 h = ggx_.sample_visible_normal(wo, u0, u1);
        const float wo_h = glm::dot(wo, h);
        s.wi = 2.0f * wo_h * h - wo;
        if (!(s.wi.z > 0.0f && wo_h > 0.0f)) return s;  // below the horizon: masked, the sample is lost
        s.pdf = ggx_.g1(wo) * ggx_.d(h) / (4.0f * wo.z);
        if (!(s.pdf > 0.0f && s.pdf < INFINITY)) return s;
        s.weight = fresnel_(fmin_float(1.0f, wo_h)) * (ggx_.g2(wo, s.wi) / ggx_.g1(wo));
        s.valid = true;
        return s;
    }

private:
    GgxDistribution ggx_;
    ConductorFresnel fresnel_;
};

}  // namespace wt
