#pragma once
// The random numbers of a chunk of diffuse vertices pushed undrawn
// (DiffuseVertexQueue::push_undrawn), drawn for the whole chunk at once: the continuation's
// (continuation_random) and each light sample's (light_sample_point), both in core/path/path_vertex.h.
// Each is VertexRandom::pair (core/sampling/rng.h), a splitmix64 hash of the vertex's base and
// the dimension. The shade loop drew them one vertex after another, a chain of 64-bit multiplies
// per number; over a chunk's array the compiler puts them in the ISA's vector lanes (AVX-512DQ
// multiplies 64-bit lanes; the narrower ISAs build the products of 32-bit ones). Integers, and
// then a 24-bit integer times 2^-24, so the same bits as one vertex at a time.

#include <cstddef>
#include <cstdint>

#include "core/sampling/rng.h"
#include "kernels/queues/diffuse_vertex_queue.h"
#include "simd/isa.h"

namespace wt::shading {
inline namespace WT_SIMD_ISA {

// VertexRandom::with_base(base[i]).pair(dimension) for i in [0, count).
inline void draw_pairs(const uint64_t* __restrict base, std::size_t count, uint32_t dimension, float* __restrict first,
                       float* __restrict second) {
    for (std::size_t i = 0; i < count; ++i) {
        const UniformPair p = VertexRandom::with_base(base[i]).pair(dimension);
        first[i] = p.first, second[i] = p.second;
    }
}

// VertexRandom::with_base(base[i])(dimension) for i in [0, count).
inline void draw_singles(const uint64_t* __restrict base, std::size_t count, uint32_t dimension, float* __restrict out) {
    for (std::size_t i = 0; i < count; ++i) out[i] = VertexRandom::with_base(base[i])(dimension);
}

// Every vertex's u0, u1 and roulette (continuation_random's), and its `light_samples` light
// samples' light_u, light_v and light_choice (light_sample_point's, the choice drawn always as
// it does for samplers whose draws are cheap: the only ones that push undrawn).
inline void draw_diffuse_random(DiffuseVertexQueue& q, uint32_t light_samples) {
    const std::size_t n = q.count;
    const uint64_t* base = q.random_base.data();
    draw_pairs(base, n, dim::bsdf_u, q.u0.data(), q.u1.data());
    draw_singles(base, n, dim::roulette, q.roulette.data());
    for (uint32_t j = 0; j < light_samples; ++j) {
        const uint32_t first = dim::light_first + dim::per_shadow_ray * j;
        const std::size_t row = j * q.stride;
        draw_pairs(base, n, first + dim::light_u, q.light_u.data() + row, q.light_v.data() + row);
        draw_singles(base, n, first + dim::light_choice, q.light_choice.data() + row);
    }
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::shading
