#pragma once
// The light samples of a rough vertex (rough_conductor, rough_glass): DirectLightSampler's
// estimate with the microfacet BSDF in place of the diffuse one, and with rough glass also
// towards lights on the far side of the surface (its refraction lobe), from an origin moved off
// the surface on that side. Weighted by the power heuristic against the BSDF's own pdf of the
// direction (MicrofacetBsdfAtView::pdf), which continue_path passes on for the emission the BSDF
// sample finds, with nee as with mis: a sharp lobe's light is found by BSDF samples, not by
// light samples (uniform over the lights' area, they almost never land in a narrow lobe), so
// light samples alone would converge too slowly to be of use. Diffuse vertices keep nee's rule.
//
// The same random dimensions as the diffuse samples (dim::light_first ...), so a vertex's light
// samples are drawn as they would be for any material.

#include <cmath>

#include <glm/geometric.hpp>

#include "core/path/estimator.h"
#include "core/materials/microfacet_bsdf.h"
#include "core/path/path_vertex.h"
#include "core/base/ray_offset.h"
#include "core/sampling/samplers.h"
#include "core/scene/scene.h"

namespace wt {

template <typename E = DefaultEstimator>
class GlossyLightSampler {
public:
    GlossyLightSampler(const Scene& scene, const Material& m, const SurfacePoint& surface, const glm::vec3& d,
                       const glm::vec3& throughput, const PathSeed& path, uint32_t bounce, uint32_t count)
        : scene_(scene),
          normal_(glm::dot(d, surface.normal) < 0.0f ? surface.normal : -surface.normal),
          position_(surface.position),
          origin_front_(offset_ray_origin(surface.position, surface.error, normal_)),
          origin_behind_(offset_ray_origin(surface.position, surface.error, -normal_)),
          throughput_(throughput),
          bsdf_(m, microfacet_normal(normal_, surface.smooth ? &surface.shading_normal : nullptr, d), normal_,
                glm::dot(d, surface.normal) < 0.0f, -d, scene.settings.accuracy.fresnel),
          random_(path, bounce, count),
          count_(count),
          count_float_(float(count)),
          bsdf_competes_(int(bounce) + 1 < scene.settings.max_bounces),
          clamp_limit_(light_sample_clamp_limit<E>(scene, bounce, count)) {}

    // Every light sample of the vertex, in index order, as DirectLightSampler::sample_all.
    template <typename Emit>
    void sample_all(Emit&& emit) const {
        ShadowRay s;
        for (uint32_t j = 0; j < count_; ++j)
            if (sample(j, s)) emit(s);
    }

    bool sample(uint32_t index, ShadowRay& s) const {
        const uint32_t base = dim::light_first + dim::per_shadow_ray * index;
        const UniformPair point = random_.pair(base + dim::light_u);
        const float choice = scene_.lights.size() > 1 ? random_(base + dim::light_choice) : 0.0f;
        const LightSample light = scene_.lights.sample(scene_.triangles, choice, point.first, point.second);
        const glm::vec3 to_light = light.position - position_;
        const float dist2 = glm::dot(to_light, to_light);
        if (!(dist2 > 0.0f)) return false;
        const glm::vec3 wi = to_light / std::sqrt(dist2);
        const float cos_y = -glm::dot(light.normal, wi);
        const float cos_x = glm::dot(normal_, wi);
        if (cos_y <= 0.0f || cos_x == 0.0f || (cos_x < 0.0f && !bsdf_.transmits())) return false;
        const glm::vec3 f_cos = bsdf_.f_cos(wi);
        if (!(f_cos.x > 0.0f || f_cos.y > 0.0f || f_cos.z > 0.0f)) return false;
        aim_shadow_ray(s, cos_x > 0.0f ? origin_front_ : origin_behind_, light);
        s.contribution = throughput_ * f_cos * light.radiance * (cos_y / (dist2 * light.pdf_area * count_float_));
        if (bsdf_competes_) {
            const float light_pdf = light.pdf_area * dist2 / cos_y;  // per unit solid angle
            s.contribution *= power_heuristic(count_float_ * light_pdf, bsdf_.pdf(wi));
        }
        if constexpr (E::clamps_indirect) s.contribution = clamped_per_channel(s.contribution, clamp_limit_);
        return true;
    }

private:
    const Scene& scene_;
    glm::vec3 normal_;  // geometric, facing the incoming ray
    glm::vec3 position_;
    glm::vec3 origin_front_, origin_behind_;  // the point moved off the surface on each side
    glm::vec3 throughput_;
    MicrofacetBsdfAtView bsdf_;
    typename E::Sampler random_;
    uint32_t count_;
    float count_float_;
    bool bsdf_competes_;
    float clamp_limit_;
};

}  // namespace wt
