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
// Dimensions 2k and 2k + 1 come from one hash (see VertexRandom), so the ones used together
// are paired: (camera_x, camera_y), (bsdf_u, bsdf_v), (bsdf_choice, roulette), and per shadow
// ray (light_u, light_v), then light_choice alone.
namespace dim {
constexpr uint32_t camera_x = 0;
constexpr uint32_t camera_y = 1;
constexpr uint32_t bsdf_u = 2;
constexpr uint32_t bsdf_v = 3;
constexpr uint32_t bsdf_choice = 4;   // glass: reflect or refract
constexpr uint32_t roulette = 5;
constexpr uint32_t light_first = 6;   // then per_shadow_ray per shadow ray, at these offsets:
constexpr uint32_t light_u = 0;       //   the point on the triangle (with light_v)
constexpr uint32_t light_v = 1;
constexpr uint32_t light_choice = 2;  //   which triangle; offset 3 is not used
constexpr uint32_t per_shadow_ray = 4;
static_assert(camera_x % 2 == 0 && bsdf_u % 2 == 0 && bsdf_choice % 2 == 0, "pairs start on even dimensions");
static_assert((light_first + light_u) % 2 == 0 && per_shadow_ray % 2 == 0, "pairs start on even dimensions");
}  // namespace dim

// The counter (bounce << 32 | dimension / 2) is spread over 64 bits by the golden ratio (Weyl
// sequence) before mixing, as splitmix64 does with its state.
constexpr uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ULL;

struct UniformPair {
    float first, second;  // dimensions 2k and 2k + 1
};

// The random numbers of one path vertex. One splitmix64 output gives two dimensions: 2k takes
// bits 40-63 and 2k + 1 bits 16-39 of the hash of counter k. The output function is Stafford's
// "Mix13", chosen for the avalanche of every output bit on every input bit (D. Stafford, "Better
// Bit Mixing", 2011), and splitmix64's whole 64-bit output passes BigCrush (Steele, Lea & Flood,
// OOPSLA 2014), so two disjoint 24-bit fields of one output serve as two independent uniforms,
// at half the cost: the hash was a seventh of the shading instructions. The tests check the
// pair's joint histogram (RandomFloat.DimensionsAndBouncesAreUncorrelated) and every sampler
// that consumes pairs. The bounce part of the counter is multiplied in once per vertex:
// key + (bounce << 32 | k) * gamma == (key + (bounce << 32) * gamma) + k * gamma modulo 2^64.
struct VertexRandom {
    uint64_t base;

    VertexRandom(uint64_t key, uint32_t bounce) : base(key + (uint64_t(bounce) << 32) * kGoldenGamma) {}
    // The vertex whose `base` a queue kept (the SIMD shade stage draws a chunk's numbers at once).
    static VertexRandom with_base(uint64_t base) { return VertexRandom(base, 0); }

    // Dimensions `dimension` and `dimension + 1`; `dimension` must be even.
    UniformPair pair(uint32_t dimension) const {
        const uint64_t h = hash(dimension);
        return {unit_float(h >> 40), unit_float((h >> 16) & 0xffffff)};
    }
    float operator()(uint32_t dimension) const {
        const uint64_t h = hash(dimension);
        return unit_float(dimension & 1 ? (h >> 16) & 0xffffff : h >> 40);
    }

private:
    uint64_t hash(uint32_t dimension) const { return mix64(base + uint64_t(dimension >> 1) * kGoldenGamma); }
    // 24 bits to [0, 1): every value is exactly representable and 1 is never hit. (Converted
    // from a 32-bit int, the same value: a vector unit converts those in one instruction.)
    static float unit_float(uint64_t bits24) { return float(int32_t(bits24)) * 0x1p-24f; }
};

inline float random_float(uint64_t key, uint32_t bounce, uint32_t dimension) { return VertexRandom(key, bounce)(dimension); }

}  // namespace wt
