#pragma once
// The photons' estimate at a camera path's vertex: the radiance the vertex reflects towards the
// path of the light the photons carry, L(x, wo) ~ sum_p f(wo, wi_p) Phi_p / (pi r^2) over the
// photons within r of x (Jensen, "Realistic Image Synthesis Using Photon Mapping", 2001, eq.
// 7.6: the constant kernel on the disk where the lookup's sphere meets a flat surface, which
// integrates to 1 there; Knaus and Zwicker 2011 allow any kernel normalised to 1).
//
// Where it is added, and why the path space stays split with no weights (PathContinuation,
// core/path/path_vertex.h): a camera path x0 (the eye), x1, ..., with x1 ... x_{j-1} mirrors or glass
// and x_j its first diffuse vertex, adds the estimate at x_j, and from x_j on counts no emission
// found by a specular bounce. The photons are the diffuse vertices of exactly the light paths
// whose first bounce is specular, so the estimate at x_j stands for every path x_j -> ... ->
// specular -> light, and the camera path's own estimators (light samples, and with mis the BSDF
// samples of emission) cover the paths x_j -> ... -> diffuse -> light. Paths whose x1 is diffuse
// are light tracing's and the camera paths' as before, and x1 ... x_k all specular before the
// light is the camera path's emission. Each path of camera -> ... -> light falls in exactly one
// of these by (is x1 diffuse; else is there a diffuse vertex; is the vertex before the light
// specular): complete and disjoint. The length caps match too: a photon at light vertex v seen
// from camera vertex x_j (bounce j - 1) makes a path of j - 1 + v surfaces, counted only where
// the camera paths would count it, j - 1 + v < max_bounces.
//
// The sum is exact and order-free: each photon's f Phi is converted to fixed point
// (core/film/fixed_point.h; the float products are exact in it above 2^-17), summed as integers
// and scaled once, so the estimate is the same bits whatever order the grid visits the photons
// in, and equals a brute-force search's.

#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "core/film/fixed_point.h"
#include "core/path/path_vertex.h"
#include "kernels/photons/photon_grid.h"

namespace wt {

struct PhotonGather {
    glm::vec3 radiance{0.0f};  // per unit throughput
    uint32_t photons = 0;      // within the radius and counted
};

// The estimate at `surface` (material m, diffuse), reached along d, from the photons that
// for_each_near(visit) visits (those within `radius` of the surface point, as
// PhotonGrid::for_each_within) that arrived after at most `max_vertex` light-path surfaces.
template <typename ForEachNear>
PhotonGather gather_photons_from(ForEachNear&& for_each_near, float radius, const Material& m,
                                 const SurfacePoint& surface, const glm::vec3& d, uint32_t max_vertex) {
    const LightSamplingPoint at = light_sampling_point(surface, d);
    const DiffuseBsdfAtView bsdf(m, at.shading_normal, -d);
    FixedPoint sum[3] = {0, 0, 0};
    PhotonGather out;
    for_each_near([&](const Photon& p, uint32_t) {
        if (p.vertex > max_vertex) return;
        // Lit on the side the path sees, by a photon of a surface facing the same way (not the
        // far side of a thin wall, nor the other wall of a corner).
        const glm::vec3 wi = -p.arriving;
        const float cos_i = glm::dot(at.normal, wi);
        if (!(cos_i > 0.0f && glm::dot(p.normal, at.normal) > 0.0f)) return;
        const glm::vec3 c = diffuse_bsdf_for_power(bsdf, at, wi, cos_i) * p.power;
        const float values[3] = {c.x, c.y, c.z};
        if (!add_fixed_point(sum, values, 3)) return;  // not finite, or beyond the sum: never in the image
        ++out.photons;
    });
    if (out.photons == 0) return out;
    const double pi = 3.14159265358979323846;
    const double inverse_area = 1.0 / (pi * double(radius) * double(radius));
    const glm::vec3 radiance(float(from_fixed_point(sum[0]) * inverse_area), float(from_fixed_point(sum[1]) * inverse_area),
                             float(from_fixed_point(sum[2]) * inverse_area));
    // Beyond a float (absurd powers on a tiny disk): nothing, rather than an infinity in the pixel.
    if (std::isfinite(radiance.x) && std::isfinite(radiance.y) && std::isfinite(radiance.z)) out.radiance = radiance;
    else out.photons = 0;
    return out;
}

// The same from the photons of `grid`.
inline PhotonGather gather_photons(const PhotonGrid& grid, const Material& m, const SurfacePoint& surface,
                                   const glm::vec3& d, uint32_t max_vertex) {
    return gather_photons_from([&](auto&& visit) { grid.for_each_within(surface.position, visit); }, grid.radius(), m,
                               surface, d, max_vertex);
}

}  // namespace wt
