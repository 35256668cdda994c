#pragma once
// The continuation of flat diffuse vertices, N at a time: continue_path
// (core/path/path_vertex.h) for a Lambertian or Oren-Nayar vertex without a shading normal, over
// a DiffuseVertexQueue, pushing the paths that go on into the next RayQueue. One generic loop,
// instantiated per ISA at its widest vector (kernels/isa/shade_<isa>.cpp) and at width 1 for the
// scalar kernels.
//
// Bit for bit what the scalar code computes, lane by lane: the same operations in the same order
// (glm's dot is (x + y) + z, its normalize multiplies by 1 / sqrt, fmax_float's NaN rule), only
// IEEE-exact ones (+ - * / sqrt, no fused multiply-add: vfloat.h), and branches as selects. So
// images stay the same on every ISA and the reference integrator, which calls continue_path, is
// still their oracle (tests/shade_kernels_test.cpp compares every output lane).

#include <cstdint>
#include <limits>

#include "core/sampling/quarter_pi_trig.h"
#include "core/sampling/sampling.h"
#include "kernels/queues/diffuse_vertex_queue.h"
#include "kernels/queues/ray_queues.h"
#include "simd/simd.h"

namespace wt::shading {
inline namespace WT_SIMD_ISA {

using simd::vbool;
using simd::vfloat;
using simd::vint;

template <int N>
struct Lanes3 {
    vfloat<N> x, y, z;
};

template <int N>
inline Lanes3<N> load3(const AlignedVector<float>& x, const AlignedVector<float>& y, const AlignedVector<float>& z,
                       std::size_t i) {
    return {vfloat<N>::load(x.data() + i), vfloat<N>::load(y.data() + i), vfloat<N>::load(z.data() + i)};
}

// glm::dot's order: (x + y) + z.
template <int N>
inline vfloat<N> dot(const Lanes3<N>& a, const Lanes3<N>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <int N>
inline Lanes3<N> select(vbool<N> m, const Lanes3<N>& a, const Lanes3<N>& b) {
    return {simd::select(m, a.x, b.x), simd::select(m, a.y, b.y), simd::select(m, a.z, b.z)};
}

template <int N>
inline Lanes3<N> negate(const Lanes3<N>& a) {
    return {-a.x, -a.y, -a.z};
}

// fmax_float / fmin_float (core/base/float_minmax.h): x when y is NaN, else maxss / minss.
template <int N>
inline vfloat<N> fmax_lanes(vfloat<N> x, vfloat<N> y) {
    return simd::select(y != y, x, simd::max(x, y));
}
template <int N>
inline vfloat<N> fmin_lanes(vfloat<N> x, vfloat<N> y) {
    return simd::select(y != y, x, simd::min(x, y));
}

// next_float_up / next_float_down (core/base/ray_offset.h).
template <int N>
inline vfloat<N> next_float_up(vfloat<N> v) {
    const vfloat<N> signed_zero_up = simd::select(v == 0.0f, vfloat<N>(0.0f), v);  // -0 steps as +0
    const vint<N> bits = simd::asInt(signed_zero_up);
    const vfloat<N> stepped = simd::asFloat(simd::select(signed_zero_up >= 0.0f, bits + vint<N>(1), bits - vint<N>(1)));
    return simd::select(v == std::numeric_limits<float>::infinity(), v, stepped);
}
template <int N>
inline vfloat<N> next_float_down(vfloat<N> v) {
    return -next_float_up<N>(-v);
}

// offset_ray_origin(p, error, n) (core/base/ray_offset.h).
template <int N>
inline Lanes3<N> offset_ray_origin(const Lanes3<N>& p, const Lanes3<N>& error, const Lanes3<N>& n) {
    const vfloat<N> distance = simd::abs(n.x) * error.x + simd::abs(n.y) * error.y + simd::abs(n.z) * error.z;
    const auto moved = [&](vfloat<N> coordinate, vfloat<N> normal) {
        const vfloat<N> offset = distance * normal;
        const vfloat<N> out = coordinate + offset;
        return simd::select(offset > 0.0f, next_float_up<N>(out), simd::select(offset < 0.0f, next_float_down<N>(out), out));
    };
    return {moved(p.x, n.x), moved(p.y, n.y), moved(p.z, n.z)};
}

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
    const Lanes3<N> w{local.x * tangent.x + local.y * bitangent.x + local.z * n.x,
                      local.x * tangent.y + local.y * bitangent.y + local.z * n.y,
                      local.x * tangent.z + local.y * bitangent.z + local.z * n.z};
    const vfloat<N> inverse_length = 1.0f / simd::sqrt(dot(w, w));
    return {w.x * inverse_length, w.y * inverse_length, w.z * inverse_length};
}

template <int N>
void continue_diffuse_vertices(const DiffuseVertexQueue& q, const DiffuseContinuation& settings, RayQueue& next) {
    alignas(64) float out[10][N];  // origin, direction, throughput, pdf of each lane
    for (std::size_t i = 0; i < q.count; i += N) {
        const Lanes3<N> d = load3<N>(q.dx, q.dy, q.dz, i);
        const Lanes3<N> geometric = load3<N>(q.nx, q.ny, q.nz, i);
        // sample_bsdf: the normal facing the incoming ray, then sample_diffuse about it.
        const Lanes3<N> n = select(dot(d, geometric) < 0.0f, geometric, negate(geometric));
        const Lanes3<N> wi =
            to_world_normalized<N>(n, sample_cosine_hemisphere<N>(vfloat<N>::load(q.u0.data() + i), vfloat<N>::load(q.u1.data() + i)));
        const vfloat<N> cos_i = dot(n, wi);
        vbool<N> alive = ~(cos_i <= 0.0f);  // lost to rounding at the horizon (NaN goes on, as in sample_diffuse)

        // f * cos / pdf: the albedo, times the Oren-Nayar factor (oren_nayar_factor).
        const Lanes3<N> wo = negate(d);
        const vfloat<N> cos_o = dot(n, wo);
        const vfloat<N> projected = fmax_lanes<N>(0.0f, dot(wi, wo) - cos_i * cos_o);
        const vfloat<N> factor = vfloat<N>::load(q.oren_nayar_a.data() + i) +
                                 vfloat<N>::load(q.oren_nayar_b.data() + i) * projected /
                                     fmax_lanes<N>(fmax_lanes<N>(cos_i, cos_o), 1e-7f);
        alignas(64) int32_t oren_nayar[N];
        for (int lane = 0; lane < N; ++lane) oren_nayar[lane] = q.flags[i + lane] & DiffuseVertexQueue::kOrenNayar;
        const vbool<N> rough = vint<N>::load(oren_nayar) != vint<N>(0);
        const Lanes3<N> albedo = load3<N>(q.albedo_r, q.albedo_g, q.albedo_b, i);
        const Lanes3<N> weight = select(rough, Lanes3<N>{albedo.x * factor, albedo.y * factor, albedo.z * factor}, albedo);

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
                                     throughput.x, throughput.y, throughput.z, cos_i * kInvPi};
        for (int k = 0; k < 10; ++k) vfloat<N>::store(out[k], lanes[k]);
        const std::size_t valid_lanes = q.count - i < std::size_t(N) ? q.count - i : std::size_t(N);
        uint32_t pushed = simd::movemask(alive) & uint32_t((uint64_t(1) << valid_lanes) - 1);
        for (; pushed != 0; pushed &= pushed - 1) {
            const int lane = __builtin_ctz(pushed);
            const std::size_t at = next.count++;
            next.ox[at] = out[0][lane], next.oy[at] = out[1][lane], next.oz[at] = out[2][lane];
            next.dx[at] = out[3][lane], next.dy[at] = out[4][lane], next.dz[at] = out[5][lane];
            next.throughput_r[at] = out[6][lane], next.throughput_g[at] = out[7][lane], next.throughput_b[at] = out[8][lane];
            if (settings.mis) next.bsdf_pdf[at] = out[9][lane];
            next.path[at] = q.path[i + lane];
            const bool elsewhere =
                settings.specular_light_elsewhere || (q.flags[i + lane] & DiffuseVertexQueue::kSpecularLightElsewhere);
            next.count_emission[at] =
                uint8_t((settings.mis ? RayQueue::kCountEmission : 0) | (elsewhere ? RayQueue::kSpecularLightElsewhere : 0));
        }
    }
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::shading
