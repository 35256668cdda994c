#pragma once
// The light points of a chunk of diffuse vertices, N at a time, from their light samples' random
// numbers (kernels/shading/diffuse_random.h): LightTable::sample (core/lights/light_table.h) over
// the chunk's rows, bit for bit, for a table of a few emitters without emission textures (the
// shade loop asks LightTable::few_untextured_emitters; others are sampled one at a time). The
// emitter is picked by counting the cdf entries the choice is not below, as LightTable::pick
// counts them, and its record taken by a select per emitter; the point is glm's arithmetic in the
// same order. A vertex that samples no light gets a point it never reads.

#include <cstddef>
#include <cstdint>

#include "core/base/ray_offset.h"
#include "core/lights/light_table.h"
#include "kernels/queues/diffuse_vertex_queue.h"
#include "kernels/shading/lanes.h"

namespace wt::shading {
inline namespace WT_SIMD_ISA {

template <int N>
inline Lanes3<N> broadcast3(const glm::vec3& v) {
    return {vfloat<N>(v.x), vfloat<N>(v.y), vfloat<N>(v.z)};
}

template <int N>
void pick_light_points(DiffuseVertexQueue& q, const LightTable& lights, uint32_t light_samples) {
    const auto& emitters = lights.emitters();
    const std::size_t candidates = emitters.size() - 1;
    const vfloat<N> pdf_area(lights.pdf_area());
    const vfloat<N> gamma(rounding_gamma(7));
    for (uint32_t j = 0; j < light_samples; ++j) {
        const std::size_t row = j * q.stride;
        for (std::size_t i = 0; i < q.count; i += N) {
            const std::size_t k = row + i;
            const vfloat<N> choice = vfloat<N>::load(q.light_choice.data() + k);
            const vfloat<N> u0 = vfloat<N>::load(q.light_u.data() + k), u1 = vfloat<N>::load(q.light_v.data() + k);
            vint<N> picked(0);
            for (std::size_t e = 0; e < candidates; ++e)
                picked = picked + simd::select(~(choice < vfloat<N>(emitters[e].cdf)), vint<N>(1), vint<N>(0));
            const LightTable::Emitter& first = emitters[0];
            Lanes3<N> v0 = broadcast3<N>(first.v0), e1 = broadcast3<N>(first.e1), e2 = broadcast3<N>(first.e2);
            Lanes3<N> normal = broadcast3<N>(first.normal), radiance = broadcast3<N>(first.radiance);
            Lanes3<N> abs_v0 = broadcast3<N>(first.abs_v0), abs_e1 = broadcast3<N>(first.abs_e1);
            Lanes3<N> abs_e2 = broadcast3<N>(first.abs_e2);
            vbool<N> parallelogram = first.parallelogram ? vbool<N>::from_bits(~0u) : vbool<N>::from_bits(0u);
            for (std::size_t e = 1; e <= candidates; ++e) {
                const LightTable::Emitter& r = emitters[e];
                const vbool<N> m = picked == vint<N>(int32_t(e));
                v0 = select(m, broadcast3<N>(r.v0), v0), e1 = select(m, broadcast3<N>(r.e1), e1);
                e2 = select(m, broadcast3<N>(r.e2), e2);
                normal = select(m, broadcast3<N>(r.normal), normal), radiance = select(m, broadcast3<N>(r.radiance), radiance);
                abs_v0 = select(m, broadcast3<N>(r.abs_v0), abs_v0), abs_e1 = select(m, broadcast3<N>(r.abs_e1), abs_e1);
                abs_e2 = select(m, broadcast3<N>(r.abs_e2), abs_e2);
                parallelogram = r.parallelogram ? parallelogram | m : simd::andnot(parallelogram, m);
            }
            // sample_uniform_triangle (core/sampling/sampling.h) where the emitter is a triangle.
            const vfloat<N> su0 = simd::sqrt(u0);
            const vfloat<N> bx = simd::select(parallelogram, u0, u1 * su0);
            const vfloat<N> by = simd::select(parallelogram, u1, vfloat<N>(1.0f) - su0);
            const auto store3 = [&](AlignedVector<float>& x, AlignedVector<float>& y, AlignedVector<float>& z,
                                    const Lanes3<N>& v) {
                vfloat<N>::store(x.data() + k, v.x), vfloat<N>::store(y.data() + k, v.y), vfloat<N>::store(z.data() + k, v.z);
            };
            // e.v0 + b.x * e.e1 + b.y * e.e2, and triangle_point_error_from_magnitudes (core/base/ray_offset.h).
            store3(q.light_px, q.light_py, q.light_pz,
                   {(v0.x + bx * e1.x) + by * e2.x, (v0.y + bx * e1.y) + by * e2.y, (v0.z + bx * e1.z) + by * e2.z});
            store3(q.light_ex, q.light_ey, q.light_ez,
                   {gamma * ((abs_v0.x + bx * abs_e1.x) + by * abs_e2.x), gamma * ((abs_v0.y + bx * abs_e1.y) + by * abs_e2.y),
                    gamma * ((abs_v0.z + bx * abs_e1.z) + by * abs_e2.z)});
            store3(q.light_nx, q.light_ny, q.light_nz, normal);
            store3(q.light_r, q.light_g, q.light_b, radiance);
            vfloat<N>::store(q.light_pdf_area.data() + k, pdf_area);
        }
    }
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::shading
