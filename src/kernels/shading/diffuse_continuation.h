#pragma once
// The continuation of diffuse vertices, N at a time: continue_path (core/path/path_vertex.h) for
// a Lambertian or Oren-Nayar vertex, flat (sample_bsdf) or about a shading normal
// (sample_bsdf_about_shading_normal: the cosine lobe about it, a direction below the geometric
// surface mirrored up through it, and folded_cosine_pdf for mis, only in vectors with a smooth
// lane), over a DiffuseVertexQueue, pushing the paths that go on into the next RayQueue. One generic loop,
// instantiated per ISA at its widest vector (kernels/isa/shade_<isa>.cpp) and at width 1 for the
// scalar kernels.
//
// Bit for bit what the scalar code computes, lane by lane: the same operations in the same order
// (glm's dot is (x + y) + z, its normalize multiplies by 1 / sqrt, fmax_float's NaN rule), only
// IEEE-exact ones (+ - * / sqrt, no fused multiply-add: vfloat.h), and branches as selects. So
// images stay the same on every ISA and the reference integrator, which calls continue_path, is
// still their oracle (tests/shade_kernels_test.cpp compares every output lane).

#include <cstdint>

#include "core/sampling/quarter_pi_trig.h"
#include "core/sampling/sampling.h"
#include "kernels/queues/diffuse_vertex_queue.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/shading/lanes.h"

namespace wt::shading {
inline namespace WT_SIMD_ISA {

// sample_cosine_hemisphere(u0, u1) (core/sampling/sampling.h): the concentric disk's two
// octant cases and its centre as selects, one division for both cases.
template <int N>
inline Lanes3<N> sample_cosine_hemisphere(vfloat<N> u0, vfloat<N> u1) {
    const vfloat<N> a = 2.0f * u0 - 1.0f;
    const vfloat<N> b = 2.0f * u1 - 1.0f;
    const vbool<N> wide = simd::abs(a) > simd::abs(b);
    const SinCosOf<vfloat<N>> t = sin_cos_quarter_pi((kPi / 4.0f) * (simd::select(wide, b, a) / simd::select(wide, a, b)));
    const vbool<N> centre = (a == 0.0f) & (b == 0.0f);
    const vfloat<N> x = simd::select(centre, vfloat<N>(0.0f), simd::select(wide, a * t.cos, b * t.sin));
    const vfloat<N> y = simd::select(centre, vfloat<N>(0.0f), simd::select(wide, a * t.sin, b * t.cos));
    return {x, y, simd::sqrt(fmax_lanes<N>(1e-12f, 1.0f - x * x - y * y))};
}

// Frame(n).to_world(local) (sampling.h: Duff et al. 2017), then glm::normalize.
template <int N>
inline Lanes3<N> to_world_normalized(const Lanes3<N>& n, const Lanes3<N>& local) {
    const vfloat<N> sign = simd::asFloat((simd::asInt(n.z) & vint<N>(INT32_MIN)) | simd::asInt(vfloat<N>(1.0f)));
    const vfloat<N> a = -1.0f / (sign + n.z);
    const vfloat<N> b = n.x * n.y * a;
    const Lanes3<N> tangent{1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
    const Lanes3<N> bitangent{b, sign + n.y * n.y * a, -n.y};
    return normalized<N>(Lanes3<N>{local.x * tangent.x + local.y * bitangent.x + local.z * n.x,
                                   local.x * tangent.y + local.y * bitangent.y + local.z * n.y,
                                   local.x * tangent.z + local.y * bitangent.z + local.z * n.z});
}

// kFolds: the queue has smooth vertices (DiffuseVertexQueue::has_smooth); without it, the flat
// code alone.
template <int N, bool kFolds>
void continue_diffuse_vertices_with(const DiffuseVertexQueue& q, const DiffuseContinuation& settings, RayQueue& next) {
    alignas(64) float out[10][N];  // origin, direction, throughput, pdf of each lane
    for (std::size_t i = 0; i < q.count; i += N) {
        const vint<N> flags = flag_lanes<N>(q.flags, i);
        const Lanes3<N> d = load3<N>(q.dx, q.dy, q.dz, i);
        const Lanes3<N> geometric = load3<N>(q.nx, q.ny, q.nz, i);
        // sample_bsdf: the normal facing the incoming ray, then sample_diffuse about it; about the
        // shading normal turned to its side where the vertex is smooth.
        const Lanes3<N> n = facing(geometric, d);
        const vbool<N> smooth = has_flag<N>(flags, DiffuseVertexQueue::kSmooth);
        const bool folds = kFolds && lanes_below(smooth, q.count - i) != 0;
        const Lanes3<N> shading = folds ? select(smooth, shading_normal_facing<N>(load3<N>(q.snx, q.sny, q.snz, i), n), n) : n;
        const Lanes3<N> sampled = to_world_normalized<N>(
            shading, sample_cosine_hemisphere<N>(vfloat<N>::load(q.u0.data() + i), vfloat<N>::load(q.u1.data() + i)));
        const vfloat<N> cos_i = dot(shading, sampled);
        vbool<N> alive = ~(cos_i <= 0.0f);  // lost to rounding at the horizon (NaN goes on, as in sample_diffuse)

        // f * cos / pdf: the albedo, times the Oren-Nayar factor (oren_nayar_factor).
        const Lanes3<N> wo = negate(d);
        const vfloat<N> cos_o = dot(shading, wo);
        const vfloat<N> factor = oren_nayar_factor<N>(vfloat<N>::load(q.oren_nayar_a.data() + i),
                                                      vfloat<N>::load(q.oren_nayar_b.data() + i), cos_i, cos_o, dot(sampled, wo));
        const vbool<N> rough = has_flag<N>(flags, DiffuseVertexQueue::kOrenNayar);
        const Lanes3<N> albedo = load3<N>(q.albedo_r, q.albedo_g, q.albedo_b, i);
        const Lanes3<N> weight = select(rough, Lanes3<N>{albedo.x * factor, albedo.y * factor, albedo.z * factor}, albedo);

        Lanes3<N> wi = sampled;
        vfloat<N> pdf = cos_i * kInvPi;  // diffuse_direction_pdf, flat
        if (folds) {
            // mirrored_to_side: below the geometric surface, mirrored through it and normalized;
            // the path ends if that is not strictly above it either.
            const vbool<N> below = ~(dot(sampled, n) > 0.0f);
            const Lanes3<N> mirrored = normalized<N>(reflect<N>(sampled, n));
            const vbool<N> mirrors = smooth & below;
            wi = select(mirrors, mirrored, sampled);
            alive = alive & ~(mirrors & ~(dot(mirrored, n) > 0.0f));
            // folded_cosine_pdf at the direction taken: with its image mirrored about the facing normal.
            const Lanes3<N> image = reflect<N>(wi, n);
            const vfloat<N> folded = (fmax_lanes<N>(0.0f, dot(shading, wi)) + fmax_lanes<N>(0.0f, dot(shading, image))) * kInvPi;
            pdf = simd::select(smooth, folded, pdf);
        }

        const Lanes3<N> incoming = load3<N>(q.throughput_r, q.throughput_g, q.throughput_b, i);
        Lanes3<N> throughput{incoming.x * weight.x, incoming.y * weight.y, incoming.z * weight.z};
        // A black surface ends the path.
        alive = alive & ((throughput.x > 0.0f) | (throughput.y > 0.0f) | (throughput.z > 0.0f));
        if (settings.roulette) {
            const vfloat<N> survival = fmin_lanes<N>(0.95f, fmax_lanes<N>(throughput.x, fmax_lanes<N>(throughput.y, throughput.z)));
            alive = alive & (vfloat<N>::load(q.roulette.data() + i) < survival);
            throughput = {throughput.x / survival, throughput.y / survival, throughput.z / survival};
        }
        const Lanes3<N> side = select(dot(wi, geometric) > 0.0f, geometric, negate(geometric));
        const Lanes3<N> origin = offset_ray_origin<N>(load3<N>(q.px, q.py, q.pz, i), load3<N>(q.ex, q.ey, q.ez, i), side);

        const vfloat<N> lanes[10] = {origin.x,     origin.y,     origin.z,     wi.x, wi.y, wi.z,
                                     throughput.x, throughput.y, throughput.z, pdf};
        for (int k = 0; k < 10; ++k) vfloat<N>::store(out[k], lanes[k]);
        for (uint32_t pushed = lanes_below(alive, q.count - i); pushed != 0; pushed &= pushed - 1) {
            const int lane = __builtin_ctz(pushed);
            const bool elsewhere =
                settings.specular_light_elsewhere || (q.flags[i + lane] & DiffuseVertexQueue::kSpecularLightElsewhere);
            if (settings.mis) next.bsdf_pdf[next.count] = out[9][lane];
            next.push({{out[0][lane], out[1][lane], out[2][lane]}, {out[3][lane], out[4][lane], out[5][lane]}},
                      {out[6][lane], out[7][lane], out[8][lane]}, q.path[i + lane],
                      uint8_t((settings.mis ? RayQueue::kCountEmission : 0) | (elsewhere ? RayQueue::kSpecularLightElsewhere : 0)));
        }
    }
}

template <int N>
void continue_diffuse_vertices(const DiffuseVertexQueue& q, const DiffuseContinuation& settings, RayQueue& next) {
    if (q.has_smooth) continue_diffuse_vertices_with<N, true>(q, settings, next);
    else continue_diffuse_vertices_with<N, false>(q, settings, next);
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::shading
