#pragma once
// The rough materials (rough_conductor, rough_glass, principled) in world space, as the path vertices use
// them: seen from one direction wo, evaluated for many wi (the light samples), or sampled (the
// next direction). Their lobes are neither diffuse nor specular: see core/path/path_vertex.h for how
// the integrators treat them.
//
// About a shading normal ns the lobe is the flat one about ns, kept only where a direction's
// side of the geometric surface agrees with its side of ns (reflections above both, refractions
// below both): a sample about ns that leaves on the wrong geometric side is lost rather than
// leaked through the surface, and the light samples drop the same directions, so both estimate
// the same (slightly darker near silhouettes) integral. A view behind ns (possible at
// silhouettes) uses the geometric normal, as the specular materials do (shading_normal_bsdf.h).

#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/base/accuracy.h"
#include "core/materials/bsdf_sample.h"
#include "core/materials/compensated_conductor.h"
#include "core/materials/conductor_fresnel.h"
#include "core/materials/multiple_scattering.h"
#include "core/materials/principled.h"
#include "core/materials/rough_conductor.h"
#include "core/materials/rough_dielectric.h"
#include "core/sampling/sampling.h"
#include "core/description/scene_description.h"

namespace wt {

inline ConductorFresnel conductor_fresnel(const Material& m) { return ConductorFresnel{m.f0, m.eta, m.k}; }

// The conductor's F_avg for its multiple-scattering lobe: Schlick's in closed form (a texture may
// have changed f0 at this hit), the complex index's as the scene builder integrated it.
inline glm::vec3 conductor_fresnel_average(const Material& m) {
    return m.eta.x > 0.0f ? m.conductor_fresnel_average : schlick_fresnel_average(m.f0);
}

// The normal a rough vertex scatters about: ns turned to the side of n_geom (unit, facing the
// incoming direction d) if d arrives in front of it, else n_geom.
inline glm::vec3 microfacet_normal(const glm::vec3& n_geom, const glm::vec3* n_shading, const glm::vec3& d) {
    if (!n_shading) return n_geom;
    const glm::vec3 ns = glm::dot(*n_shading, n_geom) < 0.0f ? -*n_shading : *n_shading;
    return glm::dot(d, ns) < 0.0f ? ns : n_geom;
}

class MicrofacetBsdfAtView {
public:
    // n: the normal to scatter about (microfacet_normal), facing wo; n_geom the geometric normal
    // facing wo; `front`: wo is on the outside of the surface (for rough glass).
    MicrofacetBsdfAtView(const Material& m, const glm::vec3& n, const glm::vec3& n_geom, bool front, const glm::vec3& wo,
                         FresnelModel fresnel)
        : frame_(n),
          n_geom_(n_geom),
          wo_(to_local(frame_, wo)),
          dielectric_(m.type == MaterialType::rough_glass),
          principled_(m.type == MaterialType::principled),
          conductor_(ggx_alpha(m.roughness), conductor_fresnel(m)),
          glass_(ggx_alpha(m.roughness), m.ior, front, fresnel),
          mixed_(m.base_color, m.metallic, m.roughness, m.ior, wo_, principled_ && m.multiple_scattering) {
        if (m.multiple_scattering && m.type == MaterialType::rough_conductor)
            compensated_.emplace(m.roughness, conductor_fresnel(m), conductor_fresnel_average(m), wo_);
    }

    bool transmits() const { return dielectric_; }

    // f(wo, wi) |n.wi|, the integrand's BSDF-times-cosine; zero where the sides disagree.
    glm::vec3 f_cos(const glm::vec3& wi) const {
        const glm::vec3 local = to_local(frame_, wi);
        if (!sides_agree(wi, local)) return glm::vec3(0.0f);
        const float cos_i = std::abs(local.z);
        if (principled_) return mixed_.f(wo_, local) * cos_i;
        if (compensated_) return compensated_->f(wo_, local) * cos_i;
        return dielectric_ ? glm::vec3(glass_.f(wo_, local) * cos_i) : conductor_.f(wo_, local) * cos_i;
    }

    // The pdf, per unit solid angle, with which sample() draws wi.
    float pdf(const glm::vec3& wi) const {
        const glm::vec3 local = to_local(frame_, wi);
        if (!sides_agree(wi, local)) return 0.0f;
        if (principled_) return mixed_.pdf(wo_, local);
        if (compensated_) return compensated_->pdf(wo_, local);
        return dielectric_ ? glass_.pdf(wo_, local) : conductor_.pdf(wo_, local);
    }

    BsdfSample sample(float u0, float u1, float u_choice) const {
        BsdfSample s;
        if (!(wo_.z > 0.0f)) return s;  // wo at the horizon after rounding
        const MicrofacetSample m = principled_    ? mixed_.sample(wo_, u0, u1, u_choice)
                                   : compensated_ ? compensated_->sample(wo_, u0, u1, u_choice)
                                   : dielectric_  ? glass_.sample(wo_, u0, u1, u_choice)
                                                  : conductor_.sample(wo_, u0, u1);
        if (!m.valid) return s;
        s.direction = glm::normalize(frame_.to_world(m.wi));
        if (!sides_agree(s.direction, to_local(frame_, s.direction))) return s;
        s.weight = m.weight;
        s.pdf = m.pdf;
        s.transmitted = m.transmitted;
        s.glossy = s.valid = true;
        return s;
    }

private:
    bool sides_agree(const glm::vec3& wi, const glm::vec3& local) const {
        const float cos_geom = glm::dot(n_geom_, wi);
        return local.z > 0.0f ? cos_geom > 0.0f : (local.z < 0.0f && cos_geom < 0.0f && dielectric_);
    }

    Frame frame_;
    glm::vec3 n_geom_;
    glm::vec3 wo_;  // local
    bool dielectric_;
    bool principled_;
    RoughConductor conductor_;
    RoughDielectric glass_;
    PrincipledBrdf mixed_;  // after wo_, which it reads
    // A rough conductor with Material::multiple_scattering; it is then the BSDF, not conductor_.
    std::optional<CompensatedConductor> compensated_;
};

// sample_bsdf for a rough material: n_geom is the geometric normal (outward, as glass reads
// it), n_shading the shading normal or null, d the incoming direction.
[[gnu::noinline]] inline BsdfSample sample_microfacet(const Material& m, const glm::vec3& n_geom, const glm::vec3* n_shading,
                                                      const glm::vec3& d, float u0, float u1, float u_choice,
                                                      FresnelModel fresnel) {
    const bool front = glm::dot(d, n_geom) < 0.0f;
    const glm::vec3 ng = front ? n_geom : -n_geom;
    return MicrofacetBsdfAtView(m, microfacet_normal(ng, n_shading, d), ng, front, -d, fresnel).sample(u0, u1, u_choice);
}

}  // namespace wt
