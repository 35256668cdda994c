#pragma once
// Counter-based random numbers. Every value is a pure function of
// (seed, pixel, sample index, bounce, dimension), as in pbrt-v4's samplers: a sample can be
// replayed alone (--debug-sample), and the image does not depend on threads, tiles or the order
// in which paths are processed.

#include <cstdint>

namespace wt {

// splitmix64's output function (Steele, Lea & Flood 2014): a bijective 64-bit mixer whose
// outputs pass BigCrush for consecutive inputs, which is exactly how we feed it.
inline uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// One key per camera path, computed once when the path starts.
inline uint64_t path_key(uint64_t seed, uint32_t pixel, uint32_t sample) {
    return mix64(mix64(seed) ^ ((uint64_t(pixel) << 32) | sample));
}

// Random dimensions consumed at each path vertex. The camera uses bounce 0's first two.
namespace dim {
constexpr uint32_t camera_x = 0;
constexpr uint32_t camera_y = 1;
constexpr uint32_t bsdf_u = 2;
constexpr uint32_t bsdf_v = 3;
constexpr uint32_t bsdf_choice = 4;   // glass: reflect or refract
constexpr uint32_t roulette = 5;
constexpr uint32_t light_first = 6;   // then 3 per shadow ray: light choice, u, v
constexpr uint32_t per_shadow_ray = 3;
}  // namespace dim

// The counter (bounce << 32 | dimension) is spread over 64 bits by the golden ratio (Weyl
// sequence) before mixing, as splitmix64 does with its state.
constexpr uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ULL;

// The random numbers of one path vertex. The counter's bounce part is multiplied in once per
// vertex: key + (bounce << 32 | d) * gamma == (key + (bounce << 32) * gamma) + d * gamma
// modulo 2^64, so vertex_random(key, bounce)(d) is random_float(key, bounce, d), bit for bit.
struct VertexRandom {
    uint64_t base;

    VertexRandom(uint64_t key, uint32_t bounce) : base(key + (uint64_t(bounce) << 32) * kGoldenGamma) {}
    // Uniform in [0, 1): the top 24 bits, so every value is exactly representable and 1 is never hit.
    float operator()(uint32_t dimension) const { return float(mix64(base + uint64_t(dimension) * kGoldenGamma) >> 40) * 0x1p-24f; }
};

inline float random_float(uint64_t key, uint32_t bounce, uint32_t dimension) { return VertexRandom(key, bounce)(dimension); }

}  // namespace wt
