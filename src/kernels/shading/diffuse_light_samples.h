#pragma once
// The light samples of diffuse vertices, N vertices at a time: DirectLightSampler::sample
// (core/path/path_vertex.h) with the flat BSDF, or the folded one about a shading normal
// (folded_diffuse, core/materials/shading_normal_bsdf.h) in the lanes of smooth vertices, over a
// DiffuseVertexQueue whose light points the shade loop has picked, pushing the shadow rays that
// can contribute into the ShadowQueue. One generic loop per ISA, as diffuse_continuation.h, and
// bit for bit the scalar code in the same way (tests/shade_kernels_test.cpp). What a vertex's
// samples share (its ray origin, the BSDF's view-dependent part) is computed once per vertex, as
// DiffuseBsdfAtView does. The folded BSDF's work is done only for vectors with a smooth lane, so
// a scene without vertex normals runs the flat code alone.
//
// Sample j of N neighbouring vertices is pushed together, then sample j + 1: each vertex's samples
// are in index order, so each path's shadow contributions are added in the order the scalar loop
// adds them (the shadow stage adds them in queue order).

#include <cstdint>

#include "core/sampling/sampling.h"
#include "kernels/queues/diffuse_vertex_queue.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/shading/lanes.h"

namespace wt::shading {
inline namespace WT_SIMD_ISA {

// DiffuseBsdfAtView::without_horizon at cos_i, per channel: Lambert's albedo / pi, or the
// albedo times Oren-Nayar's factor / pi in the `rough` lanes.
template <int N>
inline Lanes3<N> diffuse_bsdf_without_horizon(const Lanes3<N>& albedo, const Lanes3<N>& lambert, vbool<N> rough,
                                              vfloat<N> oren_nayar_a, vfloat<N> oren_nayar_b, vfloat<N> cos_i, vfloat<N> cos_o,
                                              vfloat<N> wi_dot_wo) {
    const vfloat<N> oren_nayar = kInvPi * oren_nayar_factor<N>(oren_nayar_a, oren_nayar_b, cos_i, cos_o, wi_dot_wo);
    return select(rough, Lanes3<N>{albedo.x * oren_nayar, albedo.y * oren_nayar, albedo.z * oren_nayar}, lambert);
}

// kFolds: the queue has smooth vertices (DiffuseVertexQueue::has_smooth); without it, the flat
// code alone.
template <int N, bool kFolds>
void sample_diffuse_lights_with(const DiffuseVertexQueue& q, const DiffuseLightSampling& settings, ShadowQueue& shadows) {
    alignas(64) float out[7][N];  // direction, tmax, contribution of each lane; the origin is per vertex
    alignas(64) float origins[3][N];
    const float count = float(settings.count);
    for (std::size_t i = 0; i < q.count; i += N) {
        const vint<N> flags = flag_lanes<N>(q.flags, i);
        const vbool<N> sampled = has_flag<N>(flags, DiffuseVertexQueue::kSamplesLights);
        if (lanes_below(sampled, q.count - i) == 0) continue;
        // light_sampling_point and DiffuseBsdfAtView: the facing normal, the shading normal turned
        // to its side, the origin moved off the surface on that side, the view's cosine about the
        // shading normal, f for Lambert.
        const Lanes3<N> d = load3<N>(q.dx, q.dy, q.dz, i);
        const Lanes3<N> n = facing(load3<N>(q.nx, q.ny, q.nz, i), d);
        const vbool<N> smooth = has_flag<N>(flags, DiffuseVertexQueue::kSmooth);
        const bool folds = kFolds && lanes_below(smooth & sampled, q.count - i) != 0;
        const Lanes3<N> shading = folds ? select(smooth, shading_normal_facing<N>(load3<N>(q.snx, q.sny, q.snz, i), n), n) : n;
        const Lanes3<N> position = load3<N>(q.px, q.py, q.pz, i);
        const Lanes3<N> origin = offset_ray_origin<N>(position, load3<N>(q.ex, q.ey, q.ez, i), n);
        vfloat<N>::store(origins[0], origin.x), vfloat<N>::store(origins[1], origin.y), vfloat<N>::store(origins[2], origin.z);
        const Lanes3<N> wo = negate(d);
        const vfloat<N> cos_o = dot(shading, wo);
        const Lanes3<N> albedo = load3<N>(q.albedo_r, q.albedo_g, q.albedo_b, i);
        const Lanes3<N> lambert{albedo.x * kInvPi, albedo.y * kInvPi, albedo.z * kInvPi};
        const vfloat<N> oren_nayar_a = vfloat<N>::load(q.oren_nayar_a.data() + i);
        const vfloat<N> oren_nayar_b = vfloat<N>::load(q.oren_nayar_b.data() + i);
        const vbool<N> rough = has_flag<N>(flags, DiffuseVertexQueue::kOrenNayar);
        const Lanes3<N> throughput = load3<N>(q.throughput_r, q.throughput_g, q.throughput_b, i);
        const auto bsdf = [&](vfloat<N> cos_i, const Lanes3<N>& wi) {
            return diffuse_bsdf_without_horizon<N>(albedo, lambert, rough, oren_nayar_a, oren_nayar_b, cos_i, cos_o, dot(wi, wo));
        };

        for (uint32_t j = 0; j < settings.count; ++j) {
            const std::size_t k = j * q.stride + i;
            const Lanes3<N> light = load3<N>(q.light_px, q.light_py, q.light_pz, k);
            const Lanes3<N> light_normal = load3<N>(q.light_nx, q.light_ny, q.light_nz, k);
            const vfloat<N> pdf_area = vfloat<N>::load(q.light_pdf_area.data() + k);
            const Lanes3<N> to_light{light.x - position.x, light.y - position.y, light.z - position.z};
            const vfloat<N> dist2 = dot(to_light, to_light);
            const vfloat<N> dist = simd::sqrt(dist2);
            const Lanes3<N> wi{to_light.x / dist, to_light.y / dist, to_light.z / dist};
            const vfloat<N> cos_x = dot(n, wi);
            const vfloat<N> cos_y = -dot(light_normal, wi);
            // Light seen from behind, or a point below the surface: no ray.
            const vbool<N> contributes = sampled & (dist2 > 0.0f) & ~((cos_x <= 0.0f) | (cos_y <= 0.0f));

            // DiffuseBsdfAtView: zero with the view below the surface, else Lambert or Oren-Nayar.
            const vbool<N> black = (cos_x <= 0.0f) | (cos_o <= 0.0f);
            const Lanes3<N> flat = select(black, Lanes3<N>{vfloat<N>(0.0f), vfloat<N>(0.0f), vfloat<N>(0.0f)}, bsdf(cos_x, wi));
            Lanes3<N> f = flat;
            vfloat<N> cosine_x = cos_x;
            vfloat<N> bsdf_pdf = cos_x * kInvPi;
            if (folds) {
                // folded_diffuse: f * cos about the shading normal at wi and at its mirror image
                // below the surface, wi - 2 cos_x n; the cosine is in it (cosine_x 1).
                const Lanes3<N> mirrored{wi.x - (2.0f * cos_x) * n.x, wi.y - (2.0f * cos_x) * n.y, wi.z - (2.0f * cos_x) * n.z};
                const auto lobe = [&](const Lanes3<N>& w) {
                    const vfloat<N> cos_shading = dot(shading, w);
                    const Lanes3<N> value = bsdf(cos_shading, w);
                    const vbool<N> above = cos_shading > 0.0f;
                    return Lanes3<N>{simd::select(above, value.x * cos_shading, vfloat<N>(0.0f)),
                                     simd::select(above, value.y * cos_shading, vfloat<N>(0.0f)),
                                     simd::select(above, value.z * cos_shading, vfloat<N>(0.0f))};
                };
                const Lanes3<N> direct = lobe(wi), reflected = lobe(mirrored);
                f = select(smooth, Lanes3<N>{direct.x + reflected.x, direct.y + reflected.y, direct.z + reflected.z}, flat);
                cosine_x = simd::select(smooth, vfloat<N>(1.0f), cos_x);
                if (settings.mis) {  // folded_cosine_pdf
                    const vfloat<N> folded_pdf =
                        (fmax_lanes<N>(0.0f, dot(shading, wi)) + fmax_lanes<N>(0.0f, dot(shading, mirrored))) * kInvPi;
                    bsdf_pdf = simd::select(smooth, folded_pdf, bsdf_pdf);
                }
            }
            const vfloat<N> geometry = cosine_x * cos_y / (dist2 * pdf_area * count);
            // aim_shadow_ray: to the light point moved off its own surface.
            const Lanes3<N> target = offset_ray_origin<N>(light, load3<N>(q.light_ex, q.light_ey, q.light_ez, k), light_normal);
            const Lanes3<N> span{target.x - origin.x, target.y - origin.y, target.z - origin.z};
            const vfloat<N> tmax = simd::sqrt(dot(span, span));
            vfloat<N> weight(1.0f);
            if (settings.mis) {  // power_heuristic(count * light pdf per solid angle, bsdf_pdf)
                const vfloat<N> light_pdf = pdf_area * dist2 / cos_y;
                const vfloat<N> mine = count * light_pdf;
                const vfloat<N> a = mine * mine;
                weight = a / (a + bsdf_pdf * bsdf_pdf);
            }
            // throughput * f * radiance * geometry, then the weight, then the clamp (clamped_per_channel).
            const auto contribution = [&](vfloat<N> t, vfloat<N> f_channel, const AlignedVector<float>& radiance) {
                vfloat<N> c = t * f_channel * vfloat<N>::load(radiance.data() + k) * geometry;
                if (settings.mis) c = c * weight;
                return simd::select(c > settings.clamp_limit, vfloat<N>(settings.clamp_limit), c);
            };
            const vfloat<N> lanes[7] = {span.x / tmax,
                                        span.y / tmax,
                                        span.z / tmax,
                                        tmax,
                                        contribution(throughput.x, f.x, q.light_r),
                                        contribution(throughput.y, f.y, q.light_g),
                                        contribution(throughput.z, f.z, q.light_b)};
            for (int c = 0; c < 7; ++c) vfloat<N>::store(out[c], lanes[c]);
            for (uint32_t pushed = lanes_below(contributes, q.count - i); pushed != 0; pushed &= pushed - 1) {
                const int lane = __builtin_ctz(pushed);
                ShadowRay shadow;
                shadow.ray = {{origins[0][lane], origins[1][lane], origins[2][lane]}, {out[0][lane], out[1][lane], out[2][lane]}};
                shadow.tmax = out[3][lane];
                shadow.contribution = {out[4][lane], out[5][lane], out[6][lane]};
                shadows.push(shadow, q.path[i + lane]);
            }
        }
    }
}

template <int N>
void sample_diffuse_lights(const DiffuseVertexQueue& q, const DiffuseLightSampling& settings, ShadowQueue& shadows) {
    if (q.has_smooth) sample_diffuse_lights_with<N, true>(q, settings, shadows);
    else sample_diffuse_lights_with<N, false>(q, settings, shadows);
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::shading
