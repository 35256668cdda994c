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
//   the kernel the light samples use (FoldedDiffuseAtView). For Lambert, K integrates over the
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
//
// With ns == ng every function here is the flat one, bit for bit.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/bsdf.h"
#include "core/fresnel.h"
#include "core/scene_description.h"

namespace wt {

// n_shading turned to the side of the geometric normal n_facing (the side the ray is on). For
// n_shading == +-n_facing it returns n_facing exactly.
inline glm::vec3 shading_normal_facing(const glm::vec3& n_shading, const glm::vec3& n_facing) {
    return glm::dot(n_shading, n_facing) < 0.0f ? -n_shading : n_shading;
}

// The diffuse BSDF about a shading normal as the light samples see it: f * cos, with the part
// of the cosine lobe below the geometric surface mirrored up through it (see the top of the
// file). Both normals are unit and face wo's side.
class FoldedDiffuseAtView {
public:
    FoldedDiffuseAtView(const Material& m, const glm::vec3& n_geom, const glm::vec3& n_shading, const glm::vec3& wo)
        : about_shading_(m, n_shading, wo), n_geom_(n_geom), n_shading_(n_shading) {}

    // K(wi) for wi above the geometric surface, given cos_geom = dot(n_geom, wi) > 0. Replaces
    // f * cos_geom: the cosine is already in it.
    glm::vec3 operator()(const glm::vec3& wi, float cos_geom) const {
        const glm::vec3 mirrored = wi - (2.0f * cos_geom) * n_geom_;  // wi's preimage below the surface
        return lobe(wi) + lobe(mirrored);
    }

    // f(wo, wi) when the shading normal is the geometric one: the flat BSDF, whose cosine the
    // caller multiplies in.
    glm::vec3 flat(const glm::vec3& wi, float cos_i) const { return about_shading_(wi, cos_i); }

private:
    glm::vec3 lobe(const glm::vec3& w) const {
        const float cos_shading = glm::dot(n_shading_, w);
        return cos_shading > 0.0f ? about_shading_.without_horizon(w, cos_shading) * cos_shading : glm::vec3(0.0f);
    }

    DiffuseBsdfAtView about_shading_;
    glm::vec3 n_geom_, n_shading_;
};

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

// sample_bsdf with a shading normal n_shading (unit, either orientation); n_geom as in
// sample_bsdf. Identical to sample_bsdf(m, n_geom, d, ...) when n_shading == n_geom.
inline BsdfSample sample_bsdf(const Material& m, const glm::vec3& n_geom, const glm::vec3& n_shading, const glm::vec3& d,
                              float u0, float u1, float u_choice, FresnelModel fresnel = FresnelModel::schlick) {
    if (n_shading == n_geom) return sample_bsdf(m, n_geom, d, u0, u1, u_choice, fresnel);
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
