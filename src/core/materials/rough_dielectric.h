#pragma once
// Rough glass: GGX microfacets that reflect and refract (Walter et al. 2007, "Microfacet Models
// for Refraction through Rough Surfaces", eqs. 20-21, with Heitz 2014's height-correlated G2).
// A visible normal h is drawn (ggx.h), and at h the smooth glass's own choice is made: reflect
// with probability R, the Fresnel reflectance of h by the scene's Fresnel model
// (glass_reflectance), else refract through h. So as roughness goes to zero this becomes
// sample_specular()'s glass, and the weight f |cos_i| / pdf is G2 / G1(wo) either way.
//
// Radiance's eta^2 on refraction is left out, as the smooth glass leaves it out (bsdf.h): with
// the camera and the lights outside the glass every path that enters also leaves, and the
// factors cancel. Without it the transmission term is Walter's eq. 21 times (n_i / n_o)^2,
// which is pbrt-v4's importance-transport BTDF:
//     f_t(wo, wi) = |wi.h| |wo.h| (1 - R) D(h) G2 / (|cos_i| cos_o (wi.h + wo.h / eta')^2),
// with eta' = n_wi / n_wo and the generalised half vector h ~ eta' wi + wo (Walter, eq. 16),
// turned to wo's side. Light paths (kernels/caustics) then sample exactly what camera paths
// sample, as they do for the smooth glass: reflection is symmetric, and refraction's missing
// (n_wo / n_wi)^2 of the adjoint cancels along a path the same way.
//
// Local frame: z the macro normal turned to wo's side (wo.z > 0); `front` says that side is the
// outside of the glass (index 1), the other the inside (index ior).

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/base/accuracy.h"
#include "core/materials/fresnel.h"
#include "core/materials/ggx.h"
#include "core/materials/microfacet_sample.h"

namespace wt {

// Past it a refraction's pdf is reported as this: near ior 1 the refracted lobe is nearly a delta
// (its Jacobian's denominator vanishes), and the power heuristic squares pdfs. The weight
// G2 / G1 does not use the pdf, and the light samples' weights read the same capped value,
// so the multiple importance weights still sum to one.
constexpr float kMaxMicrofacetPdf = 1e16f;

class RoughDielectric {
public:
    RoughDielectric(float alpha, float ior, bool front, FresnelModel fresnel)
        : ggx_(alpha),
          ior_(ior),
          eta_incident_(front ? 1.0f / ior : ior),
          eta_other_(front ? ior : 1.0f / ior),
          front_(front),
          fresnel_(fresnel) {}

    float f(const glm::vec3& wo, const glm::vec3& wi) const {
        Lobe l;
        if (!lobe(wo, wi, l)) return 0.0f;
        const float g2 = ggx_.g2(wo, wi);
        float value;
        if (!l.transmitted) {
            value = l.reflectance * ggx_.d(l.h) * g2 / (4.0f * wo.z * wi.z);
        } else {
            const float wi_h = glm::dot(wi, l.h), wo_h = glm::dot(wo, l.h);
            const float denominator = wi_h + wo_h / eta_other_;
            value = std::abs(wi_h * wo_h) * (1.0f - l.reflectance) * ggx_.d(l.h) * g2 /
                    (denominator * denominator * std::abs(wi.z) * wo.z);
        }
        return std::isfinite(value) ? value : 0.0f;
    }

    float pdf(const glm::vec3& wo, const glm::vec3& wi) const {
        Lobe l;
        if (!lobe(wo, wi, l)) return 0.0f;
        return lobe_pdf(wo, wi, l);
    }

    MicrofacetSample sample(const glm::vec3& wo, float u0, float u1, float u_choice) const {
        MicrofacetSample s;
        Lobe l;
        l.h = ggx_.sample_visible_normal(wo, u0, u1);
        if (!(glm::dot(wo, l.h) > 0.0f)) return s;
        const auto refracted = refract(-wo, l.h, eta_incident_);
        l.reflectance = glass_reflectance(-wo, l.h, refracted, front_, ior_, eta_incident_, fresnel_);
        l.transmitted = refracted && u_choice >= l.reflectance;
        s.wi = l.transmitted ? refracted->direction : glm::normalize(reflect(-wo, l.h));
        s.transmitted = l.transmitted;
        // Reflected below the surface, or refracted back above it: masked, the sample is lost.
        if (l.transmitted ? !(s.wi.z < 0.0f) : !(s.wi.z > 0.0f)) return s;
        s.pdf = lobe_pdf(wo, s.wi, l);
        if (!(s.pdf > 0.0f)) return s;
        s.weight = glm::vec3(ggx_.g2(wo, s.wi) / ggx_.g1(wo));
        s.valid = true;
        return s;
    }

private:
    struct Lobe {
        glm::vec3 h{0.0f, 0.0f, 1.0f};  // the microfacet normal, on wo's side
        float reflectance = 0.0f;        // its Fresnel reflectance for light from wo
        bool transmitted = false;
    };

    // The microfacet that takes wo to wi, if any faces both the right way.
    bool lobe(const glm::vec3& wo, const glm::vec3& wi, Lobe& l) const {
        if (!(wo.z > 0.0f) || wi.z == 0.0f || !std::isfinite(wi.z)) return false;
        l.transmitted = wi.z < 0.0f;
        const glm::vec3 sum = l.transmitted ? eta_other_ * wi + wo : wo + wi;
        const float length2 = glm::dot(sum, sum);
        if (!(length2 > 0.0f)) return false;
        l.h = sum / std::sqrt(length2);
        if (l.h.z < 0.0f) l.h = -l.h;
        // A microfacet seen from behind by either direction reflects or refracts nothing.
        if (!(glm::dot(wo, l.h) > 0.0f) || glm::dot(wi, l.h) * wi.z <= 0.0f) return false;
        const auto refracted = refract(-wo, l.h, eta_incident_);
        // Refraction through h would need light that total internal reflection turns back.
        if (l.transmitted && !refracted) return false;
        l.reflectance = glass_reflectance(-wo, l.h, refracted, front_, ior_, eta_incident_, fresnel_);
        return true;
    }

    // The visible normal's pdf, times the Jacobian from h to wi (Walter, eqs. 14 and 17) and the
    // probability of the branch.
    float lobe_pdf(const glm::vec3& wo, const glm::vec3& wi, const Lobe& l) const {
        const float visible = ggx_.visible_normal_pdf(wo, l.h);
        float p;
        if (!l.transmitted) {
            p = visible / (4.0f * glm::dot(wo, l.h)) * l.reflectance;
        } else {
            const float denominator = glm::dot(wi, l.h) + glm::dot(wo, l.h) / eta_other_;
            p = visible * std::abs(glm::dot(wi, l.h)) / (denominator * denominator) * (1.0f - l.reflectance);
        }
        return std::isnan(p) ? 0.0f : fmin_float(p, kMaxMicrofacetPdf);
    }

    GgxDistribution ggx_;
    float ior_;
    float eta_incident_;  // n_wo / n_other, as refract() takes it
    float eta_other_;     // n_other / n_wo: pbrt-v4's eta'
    bool front_;
    FresnelModel fresnel_;
};

}  // namespace wt
