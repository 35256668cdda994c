#pragma once
// The continuation at flat mirror and glass vertices, N at a time, of light paths (what
// LightPathTracer::at_vertex, kernels/caustics/light_path.cpp, does there) and of camera paths
// (what continue_path, core/path/path_vertex.h, does): sample_specular (core/materials/bsdf.h:
// the mirror direction; for glass, Snell's refraction, the reflectance by Schlick's
// approximation or the exact Fresnel equations, and the choice between the two), the weight,
// Russian roulette and the offset origin, over a SpecularVertexQueue, appending the paths that
// go on to a RayQueue. One generic loop, instantiated per ISA at its widest vector
// (kernels/isa/shade_<isa>.cpp) and at width 1 for the scalar kernels.
//
// Bit for bit what the scalar code computes, lane by lane (the same operations in the same
// order, branches as selects): tests/specular_continuation_test.cpp holds every ISA's rays to
// at_vertex's and continue_path's.

#include <cstdint>

#include "core/base/accuracy.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/queues/specular_vertex_queue.h"
#include "kernels/shading/lanes.h"

namespace wt::shading {
inline namespace WT_SIMD_ISA {

// Appends the next ray of every entry of `q` whose path goes on, in the queue's order.
// `roulette`: Russian roulette at this vertex (vertex > rr_start_bounce).
template <int N>
void continue_specular_vertices(const SpecularVertexQueue& q, bool roulette, FresnelModel fresnel, RayQueue& next) {
    alignas(64) float out[9][N];  // origin, direction, weight of each lane
    for (std::size_t i = 0; i < q.count; i += N) {
        const Lanes3<N> d = load3<N>(q.dx, q.dy, q.dz, i);
        const Lanes3<N> geometric = load3<N>(q.nx, q.ny, q.nz, i);
        // sample_bsdf: the normal facing the arriving ray, and which side of the glass it came from.
        const vbool<N> front = dot(d, geometric) < 0.0f;
        const Lanes3<N> n = select(front, geometric, negate(geometric));
        const Lanes3<N> mirrored = normalized<N>(reflect<N>(d, n));

        // Glass (sample_specular): refract, then reflect with the Fresnel reflectance's probability.
        const vfloat<N> ior = vfloat<N>::load(q.ior.data() + i);
        const vfloat<N> eta = simd::select(front, 1.0f / ior, ior);
        const vfloat<N> cos_i = -dot(d, n);
        const vfloat<N> sin2_t = eta * eta * fmax_lanes<N>(0.0f, 1.0f - cos_i * cos_i);
        const vbool<N> refracts = ~(sin2_t >= 1.0f);  // else total internal reflection
        const vfloat<N> cos_t = simd::sqrt(1.0f - sin2_t);
        const vfloat<N> along_n = eta * cos_i - cos_t;
        const Lanes3<N> refracted =
            normalized<N>(Lanes3<N>{eta * d.x + along_n * n.x, eta * d.y + along_n * n.y, eta * d.z + along_n * n.z});
        vfloat<N> reflectance;
        if (fresnel == FresnelModel::exact) {
            // fresnel_dielectric(cos_i, cos_t, eta)
            const vfloat<N> rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
            const vfloat<N> rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
            reflectance = 0.5f * (rs * rs + rp * rp);
        } else {
            // schlick_reflectance(front ? cos_i : cos_t, ior)
            vfloat<N> r0 = (1.0f - ior) / (1.0f + ior);
            r0 = r0 * r0;
            const vfloat<N> m = 1.0f - simd::select(front, cos_i, cos_t);
            const vfloat<N> m2 = m * m;
            reflectance = simd::select(ior == 1.0f, vfloat<N>(0.0f), r0 + (1.0f - r0) * (m2 * m2 * m));
        }
        const vbool<N> glass = has_flag<N>(flag_lanes<N>(q.glass, i), 1);
        const vbool<N> transmits = glass & refracts & (vfloat<N>::load(q.choice.data() + i) >= reflectance);
        const Lanes3<N> direction = select(transmits, refracted, mirrored);

        // The weight: the mirror's reflectance, glass's 1 (R / R either way).
        const Lanes3<N> arriving = load3<N>(q.weight_r, q.weight_g, q.weight_b, i);
        const Lanes3<N> bsdf = select(glass, Lanes3<N>{vfloat<N>(1.0f), vfloat<N>(1.0f), vfloat<N>(1.0f)},
                                      load3<N>(q.reflectance_r, q.reflectance_g, q.reflectance_b, i));
        Lanes3<N> weight{arriving.x * bsdf.x, arriving.y * bsdf.y, arriving.z * bsdf.z};
        vbool<N> alive = vbool<N>(true);
        if (roulette) {
            const vfloat<N> survival = fmin_lanes<N>(0.95f, fmax_lanes<N>(weight.x, fmax_lanes<N>(weight.y, weight.z)));
            alive = vfloat<N>::load(q.roulette.data() + i) < survival;
            weight = {weight.x / survival, weight.y / survival, weight.z / survival};
        }
        alive = alive & ((weight.x > 0.0f) | (weight.y > 0.0f) | (weight.z > 0.0f));
        const Lanes3<N> side = select(dot(direction, geometric) > 0.0f, geometric, negate(geometric));
        const Lanes3<N> origin = offset_ray_origin<N>(load3<N>(q.px, q.py, q.pz, i), load3<N>(q.ex, q.ey, q.ez, i), side);

        const vfloat<N> lanes[9] = {origin.x, origin.y, origin.z, direction.x, direction.y, direction.z, weight.x, weight.y, weight.z};
        for (int k = 0; k < 9; ++k) vfloat<N>::store(out[k], lanes[k]);
        for (uint32_t pushed = lanes_below(alive, q.count - i); pushed != 0; pushed &= pushed - 1) {
            const int lane = __builtin_ctz(pushed);
            // A specular bounce's pdf is 0 (continue_path), read only with mis or kRoughPdf.
            next.bsdf_pdf[next.count] = 0.0f;
            next.push({{out[0][lane], out[1][lane], out[2][lane]}, {out[3][lane], out[4][lane], out[5][lane]}},
                      {out[6][lane], out[7][lane], out[8][lane]}, q.path[i + lane], q.next_flags[i + lane]);
        }
    }
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::shading
