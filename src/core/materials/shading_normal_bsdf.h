#pragma once
// Scattering about a shading normal ns (an interpolated vertex normal) on a surface whose
// geometric normal ng still decides which side a direction is on. ns and ng disagree, so three
// things can go wrong (Veach's thesis, sec. 5.3; pbrt-v4, sec. 10.1.1): a direction sampled
// about ns can point below the geometric surface and leak through it; a BSDF evaluated about ns
// is zero where the viewer is above the surface but below ns (a black facet); and the light
// samples must see exactly the BSDF times cosine that BSDF sampling draws from, or the two
// estimate different integrals. The model here:
//
// - ns is turned to the side of ng the ray arrived on (vertex normals may be wound either way).
// - Diffuse: sample the cosine lobe about ns with the usual weight (albedo times the Oren-Nayar
//   factor, evaluated about ns). A direction w below the geometric surface is mirrored through
//   its tangent plane, w' = w - 2 (w.ng) ng, weight kept. The mirror is its own inverse with
//   Jacobian 1, so a direction w above the surface is reached from w and from w', and what the
//   sampler estimates is the integral of L(w) against
//       K(w) = f(w) max(0, ns.w) + f(w') max(0, ns.w'),
//   the kernel the light samples use (folded_diffuse). For Lambert, K integrates over the
//   geometric hemisphere to rho/pi times the integral of max(0, ns.w) over the whole sphere,
//   which is rho: no energy is lost or gained whatever ns is (tangent, tilted, opposite), so
//   the white furnace holds exactly, and no direction ever leaves through the surface.
//   Oren-Nayar's f is the same about ns (never above Lambert's albedo; see
//   DiffuseBsdfAtView::without_horizon), so it loses what it loses on a flat surface.
// - Mirror and glass: reflect and refract about ns, deciding inside/outside by ng. A result on
//   the wrong geometric side (reflected into the surface, refracted back out) is mirrored
//   through the tangent plane like a diffuse direction; a ray arriving behind ns (possible at
//   silhouettes) scatters about ng, as a flat surface would. Weights are unchanged, so
//   specular scattering neither gains nor loses energy.
// - Rough conductor and glass: about ns where the sides agree (microfacet_bsdf.h).
//
// Only vertices whose shading normal differs from the geometric one (SurfacePoint::smooth) come
// here; the others run the flat code, bit for bit as before.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/materials/bsdf.h"
#include "core/materials/fresnel.h"
#include "core/description/scene_description.h"

namespace wt {

// n_shading turned to the side of the geometric normal n_facing (the side the ray is on). For
// n_shading == +-n_facing it returns n_facing exactly.
inline glm::vec3 shading_normal_facing(const glm::vec3& n_shading, const glm::vec3& n_facing) {
    return glm::dot(n_shading, n_facing) < 0.0f ? -n_shading : n_shading;
}

// The diffuse BSDF about a shading normal as the light samples see it: f * cos, with the part
// of the cosine lobe below the geometric surface mirrored up through it (see the top of the
// file). `about_shading` is the BSDF seen from wo about n_shading; both normals are unit and face
// wo's side. For wi above the geometric surface, given cos_geom = dot(n_geom, wi) > 0; replaces
// f * cos_geom: the cosine is already in it.
inline glm::vec3 folded_diffuse(const DiffuseBsdfAtView& about_shading, const glm::vec3& n_geom, const glm::vec3& n_shading,
                                const glm::vec3& wi, float cos_geom) {
    auto lobe = [&](const glm::vec3& w) {
        const float cos_shading = glm::dot(n_shading, w);
        return cos_shading > 0.0f ? about_shading.without_horizon(w, cos_shading) * cos_shading : glm::vec3(0.0f);
    };
    const glm::vec3 mirrored = wi - (2.0f * cos_geom) * n_geom;  // wi's preimage below the surface
    return lobe(wi) + lobe(mirrored);
}

// The pdf, per unit solid angle, with which sample_bsdf_about_shading_normal draws a diffuse
// direction wi above the geometric surface (cos_geom = dot(n_geom, wi) > 0): the cosine lobe
// about n_shading at wi plus at its mirror image below the surface, the two ways to reach wi.
// Normals as in folded_diffuse. The multiple importance weights need it.
inline float folded_cosine_pdf(const glm::vec3& n_geom, const glm::vec3& n_shading, const glm::vec3& wi, float cos_geom) {
    const glm::vec3 mirrored = wi - (2.0f * cos_geom) * n_geom;
    return (fmax_float(0.0f, glm::dot(n_shading, wi)) + fmax_float(0.0f, glm::dot(n_shading, mirrored))) * kInvPi;
}

// w if it is strictly on the side of the unit normal `side`, else w mirrored through the plane
// of `side`; `ok` says whether the result is strictly on that side (false only for w exactly in
// the plane, or not finite).
inline glm::vec3 mirrored_to_side(const glm::vec3& w, const glm::vec3& side, bool& ok) {
    if (glm::dot(w, side) > 0.0f) {
        ok = true;
        return w;
    }
    const glm::vec3 m = glm::normalize(reflect(w, side));
    ok = glm::dot(m, side) > 0.0f;
    return m;
}

// sample_bsdf about a shading normal n_shading (unit, either orientation; see the top of the
// file); n_geom, d and the rest as in sample_bsdf. Out of line: only vertices with a shading
// normal call it, and inlined next to sample_bsdf it made g++ stop inlining the whole path
// continuation into the shade loop.
[[gnu::noinline]] inline BsdfSample sample_bsdf_about_shading_normal(const Material& m, const glm::vec3& n_geom,
                                                                     const glm::vec3& n_shading, const glm::vec3& d,
                                                                     float u0, float u1, float u_choice, FresnelModel fresnel) {
    if (m.is_microfacet()) return sample_microfacet(m, n_geom, &n_shading, d, u0, u1, u_choice, fresnel);
    const bool front = glm::dot(d, n_geom) < 0.0f;
    const glm::vec3 ng = front ? n_geom : -n_geom;  // facing the incoming ray
    const glm::vec3 ns = shading_normal_facing(n_shading, ng);
    if (!m.is_specular()) {
        BsdfSample s = sample_diffuse(m, ns, d, u0, u1);
        if (s.valid) s.direction = mirrored_to_side(s.direction, ng, s.valid);
        return s;
    }
    if (glm::dot(d, ns) < 0.0f) {
        BsdfSample s = sample_specular(m, ns, front, d, u_choice, fresnel);
        bool ok;
        s.direction = mirrored_to_side(s.direction, s.transmitted ? -ng : ng, ok);
        if (ok) return s;
    }
    return sample_specular(m, ng, front, d, u_choice, fresnel);
}

}  // namespace wt
