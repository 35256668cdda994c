#pragma once
// A GGX reflection lobe beside lobes that a cosine distribution samples (the principled
// material's diffuse lobe, the multiple-scattering lobe), sampled as one: the GGX lobe's
// visible normals with probability p, else the cosine hemisphere, and every sample weighted with
// the one-sample mixture pdf p pdf_ggx + (1 - p) cos_i / pi whichever drew it (pbrt-v4's and
// Mitsuba's way for layered lobes), so the estimate is unbiased for any p in (0, 1] as long as
// p < 1 wherever the other lobes reflect. Local frame: z the macro normal, wo.z > 0.

#include <cmath>

#include <glm/vec3.hpp>

#include "core/materials/microfacet_sample.h"
#include "core/materials/rough_conductor.h"
#include "core/sampling/sampling.h"

namespace wt {

class GgxCosineMixture {
public:
    GgxCosineMixture(const RoughConductor& ggx, float ggx_probability) : ggx_(ggx), ggx_probability_(ggx_probability) {}

    float pdf(const glm::vec3& wo, const glm::vec3& wi) const {
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
        return ggx_probability_ * ggx_.pdf(wo, wi) + (1.0f - ggx_probability_) * wi.z * kInvPi;
    }

    // u_choice picks the lobe, (u0, u1) the direction within it; f(wo, wi) is the whole BSDF.
    template <typename F>
    MicrofacetSample sample(const glm::vec3& wo, float u0, float u1, float u_choice, F&& f) const {
        MicrofacetSample s;
        if (u_choice < ggx_probability_) {
            const MicrofacetSample specular = ggx_.sample(wo, u0, u1);
            if (!specular.valid) return s;
            s.wi = specular.wi;
        } else {
            s.wi = sample_cosine_hemisphere(u0, u1);
        }
        if (!(s.wi.z > 0.0f)) return s;
        s.pdf = pdf(wo, s.wi);
        if (!(s.pdf > 0.0f && s.pdf < INFINITY)) return s;
        s.weight = f(wo, s.wi) * (s.wi.z / s.pdf);
        s.valid = true;
        return s;
    }

private:
    const RoughConductor& ggx_;
    float ggx_probability_;
};

}  // namespace wt
