#pragma once
// The scattering models, shared by the reference integrator and the wavefront shade kernel so
// both estimate exactly the same integral. Directions are unit vectors pointing away from the
// surface (wo towards the viewer, wi towards the light / next vertex).

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/base/float_minmax.h"
#include "core/materials/bsdf_sample.h"
#include "core/materials/conductor_fresnel.h"
#include "core/materials/fresnel.h"
#include "core/materials/microfacet_bsdf.h"
#include "core/sampling/sampling.h"
#include "core/description/scene_description.h"

namespace wt {

// Qualitative Oren-Nayar (Oren & Nayar 1994, eq. 30) coefficients: A + B * max(0, cos(phi_i - phi_o))
// * sin(alpha) * tan(beta). At sigma = 0, A = 1 and B = 0: exactly Lambertian.
//
// Energy: the model's directional albedo, rho * (A + B * g(theta_o)), peaks at grazing view,
// where g = E_cos[max(0, cos dphi) tan(theta_i)] = (1/pi) * (pi/2) = 1/2. For sigma near 0.3,
// A + B/2 reaches 1.0054: the published model reflects more than rho there. We scale A and B by
// 1 / max(1, A + B/2), which changes nothing at sigma = 0 or sigma >= 0.33 and otherwise by at
// most 0.54%, so the albedo never exceeds rho (checked by quadrature in bsdf_test).
struct OrenNayarTerms {
    float a, b;
};
inline OrenNayarTerms oren_nayar_terms(float sigma) {
    const float s2 = sigma * sigma;
    const float a = 1.0f - 0.5f * s2 / (s2 + 0.33f);
    const float b = 0.45f * s2 / (s2 + 0.09f);
    const float energy_scale = 1.0f / fmax_float(1.0f, a + 0.5f * b);
    return {a * energy_scale, b * energy_scale};
}

// The Oren-Nayar factor (A + B ...) written without angles: cos(phi_i - phi_o) sin(theta_i)
// sin(theta_o) is the dot product of wi and wo projected onto the tangent plane, and
// sin(alpha) tan(beta) = sin_i sin_o / max(cos_i, cos_o). This avoids atan/acos and the
// 0/0 of the azimuth at normal incidence. The floor on the divisor keeps a sample with
// both directions exactly grazing finite (its cosine factor makes its true weight vanish).
inline float oren_nayar_factor(const OrenNayarTerms& on, float cos_i, float cos_o, float wi_dot_wo) {
    const float projected = fmax_float(0.0f, wi_dot_wo - cos_i * cos_o);
    return on.a + on.b * projected / fmax_float(fmax_float(cos_i, cos_o), 1e-7f);
}

// A diffuse BSDF seen from one direction wo, evaluated for many wi: a vertex does this once per
// light sample, so what depends only on wo (its cosine, albedo / pi, the Oren-Nayar
// coefficients and their three divisions) is computed once, in the constructor.
class DiffuseBsdfAtView {
public:
    // n faces wo's side.
    DiffuseBsdfAtView(const Material& m, const glm::vec3& n, const glm::vec3& wo)
        : wo_(wo),
          albedo_(m.albedo),
          lambert_(m.albedo * kInvPi),
          cos_o_(glm::dot(n, wo)),
          oren_nayar_(m.type == MaterialType::lambertian ? OrenNayarTerms{1.0f, 0.0f} : oren_nayar_terms(m.sigma)),
          lambertian_(m.type == MaterialType::lambertian) {}

    // f(wo, wi), given cos_i = dot(n, wi). Zero below the surface.
    glm::vec3 operator()(const glm::vec3& wi, float cos_i) const {
        if (cos_i <= 0.0f || cos_o_ <= 0.0f) return glm::vec3(0.0f);
        return without_horizon(wi, cos_i);
    }

    // f(wo, wi) for cos_i > 0 whatever side of n wo is on: about a shading normal, wo may be
    // below it while above the geometric surface, and zero there would be a black facet.
    // (Oren-Nayar's formula stays finite and below rho's albedo for cos_o < 0: its divisor is
    // then cos_i, and sin_o < 1 only lowers the B term.)
    glm::vec3 without_horizon(const glm::vec3& wi, float cos_i) const {
        if (lambertian_) return lambert_;
        return albedo_ * (kInvPi * oren_nayar_factor(oren_nayar_, cos_i, cos_o_, glm::dot(wi, wo_)));
    }

private:
    glm::vec3 wo_, albedo_, lambert_;
    float cos_o_;
    OrenNayarTerms oren_nayar_;
    bool lambertian_;
};

// BSDF value f(wo, wi) of a diffuse material; n faces wo's side. Zero below the surface.
inline glm::vec3 eval_diffuse_bsdf(const Material& m, const glm::vec3& n, const glm::vec3& wo, const glm::vec3& wi) {
    return DiffuseBsdfAtView(m, n, wo)(wi, glm::dot(n, wi));
}

// The two halves of sample_bsdf, also called about a shading normal (shading_normal_bsdf.h).
// Always inlined, each into both callers, so sample_bsdf compiles to what it was as one function.

// A cosine-weighted direction about n (unit, facing the incoming direction d) and its weight
// f * cos / pdf for a diffuse material. Invalid when rounding puts it on n's horizon.
[[gnu::always_inline]] inline BsdfSample sample_diffuse(const Material& m, const glm::vec3& n, const glm::vec3& d, float u0,
                                                        float u1) {
    BsdfSample s;
    const glm::vec3 local = sample_cosine_hemisphere(u0, u1);
    s.direction = glm::normalize(Frame(n).to_world(local));
    const float cos_i = glm::dot(n, s.direction);
    if (cos_i <= 0.0f) return s;  // lost to rounding at the horizon
    // f * cos / pdf with pdf = cos / pi: the albedo times the Oren-Nayar factor.
    s.weight = m.albedo;
    if (m.type == MaterialType::oren_nayar) {
        const glm::vec3 wo = -d;
        s.weight *= oren_nayar_factor(oren_nayar_terms(m.sigma), cos_i, glm::dot(n, wo), glm::dot(s.direction, wo));
    }
    s.valid = true;
    return s;
}

// Mirror or glass about n (unit, facing the incoming direction d: dot(d, n) < 0). `front` says
// whether d arrived from the outside of the glass (the side its geometric normal faces).
[[gnu::always_inline]] inline BsdfSample sample_specular(const Material& m, const glm::vec3& n, bool front, const glm::vec3& d,
                                                         float u_choice, FresnelModel fresnel) {
    BsdfSample s;
    s.specular = s.valid = true;
    if (m.type == MaterialType::mirror) {
        s.direction = glm::normalize(reflect(d, n));
        s.weight = m.reflectance;
        return s;
    }
    if (m.type == MaterialType::conductor) {  // the mirror's direction, the metal's Fresnel weight
        s.direction = glm::normalize(reflect(d, n));
        s.weight = conductor_fresnel(m)(fmin_float(1.0f, -glm::dot(d, n)));
        return s;
    }
    // Radiance's eta^2 scaling on refraction is left out: with the camera and every light
    // outside the glass, each path that enters also leaves and the factors cancel.
    const float eta = front ? 1.0f / m.ior : m.ior;
    const auto refracted = refract(d, n, eta);
    s.weight = glm::vec3(1.0f);
    // Choosing reflection with probability R makes the weight R / R = 1 either way.
    if (refracted && u_choice >= glass_reflectance(d, n, refracted, front, m.ior, eta, fresnel)) {
        s.direction = refracted->direction;
        s.transmitted = true;
        return s;
    }
    s.direction = glm::normalize(reflect(d, n));  // Fresnel reflection or total internal reflection
    return s;
}

// Samples the next direction. n_geom is the geometric normal (outward for spheres, winding for
// triangles); d the incoming ray direction. u_choice and the Fresnel model only matter for the
// glasses; u0 and u1 for the diffuse and rough materials.
// Inside/outside of glass is decided by the geometric normal: spheres' normals point outward.
// Out of line, as g++ chose before there was a second sampler next to it: inlined into the path
// continuation it costs the shade loop more than the call.
[[gnu::noinline]] inline BsdfSample sample_bsdf(const Material& m, const glm::vec3& n_geom, const glm::vec3& d, float u0,
                                                float u1, float u_choice, FresnelModel fresnel = FresnelModel::schlick) {
    const bool front = glm::dot(d, n_geom) < 0.0f;
    const glm::vec3 n = front ? n_geom : -n_geom;  // facing the incoming ray
    if (m.is_specular()) return sample_specular(m, n, front, d, u_choice, fresnel);
    if (m.is_microfacet()) return sample_microfacet(m, n_geom, nullptr, d, u0, u1, u_choice, fresnel);
    return sample_diffuse(m, n, d, u0, u1);
}

}  // namespace wt
