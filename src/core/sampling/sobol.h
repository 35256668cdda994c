#pragma once
// Owen-scrambled Sobol' points in one and two dimensions, after Burley, "Practical Hash-based
// Owen Scrambling" (JCGT 2020), the sampler Cycles and pbrt-v4 use.
//
// - Points: the first two Sobol' dimensions. Dimension 0 is the van der Corput sequence (the
//   index's bits reversed); dimension 1's generator matrix comes from the primitive polynomial
//   x + 1 (Joe & Kuo's first), whose columns are v_k = v_{k-1} xor (v_{k-1} >> 1). Together
//   they are a (0, 2)-sequence: every aligned block of 2^m points has exactly one point in each
//   of the 2^m elementary intervals of any shape 2^-a x 2^-b, a + b = m.
// - Randomisation: nested uniform (Owen) scrambling in base 2, a random flip of each digit that
//   depends on the digits above it. Burley does it with a hash that lets each bit of a word
//   depend only on the bits below it (the Laine-Karras construction), applied to the value with
//   its bits reversed; the constants are Vegdahl's ("Building a Better LK Hash", 2021), which
//   mix the high bits better than the paper's. Owen scrambling keeps the net property and makes
//   every point uniform on [0, 1)^2, so estimates stay unbiased.
// - Shuffling: the same scramble applied to the point's index (Burley sec. 4) gives each pixel
//   and each pad its own order of the points: for 2^m samples the indices of one pixel are an
//   aligned block of 2^m, so its points are still a (0, m, 2)-net, and two pads shuffled with
//   independent seeds are uncorrelated (this is what "padding" means: Kollig & Keller 2002).

#include <cstdint>

namespace wt {

// The bytes by one bswap, then the bits within each byte.
inline uint32_t reverse_bits32(uint32_t v) {
    v = __builtin_bswap32(v);
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    return ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
}

// A random bijection of 32-bit words in which bit k of the result depends only on bits 0..k of
// the input (and the seed): every step is an addition, a multiplication by an odd number, or an
// xor with the word times an even number, and each carries information upwards only.
inline uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// Owen scrambling of a fixed-point fraction (bit 31 the first binary digit): each digit is
// flipped by a function of the digits before it.
inline uint32_t owen_scramble(uint32_t v, uint32_t seed) {
    return reverse_bits32(laine_karras_permutation(reverse_bits32(v), seed));
}

// Unscrambled Sobol' point `index` as 32-bit fractions, and dimension 1 with its bits reversed.
// Dimension 1's generator is the Pascal matrix mod 2: digit r of the point is the xor of the
// index bits k with binom(k, r) odd, which by Lucas' theorem are the k whose set bits include
// r's. That xor over supersets is five shift-and-mask steps (a subset-sum transform over the
// five bits of a bit position), not a loop over the index's 32 bits.
inline uint32_t sobol_dimension0(uint32_t index) { return reverse_bits32(index); }
inline uint32_t sobol_dimension1_reversed(uint32_t index) {
    uint32_t x = index;
    x ^= (x >> 1) & 0x55555555u;
    x ^= (x >> 2) & 0x33333333u;
    x ^= (x >> 4) & 0x0f0f0f0fu;
    x ^= (x >> 8) & 0x00ff00ffu;
    x ^= (x >> 16) & 0x0000ffffu;
    return x;
}
inline uint32_t sobol_dimension1(uint32_t index) { return reverse_bits32(sobol_dimension1_reversed(index)); }

// 32-bit fraction to [0, 1): the top 24 bits, every value exactly a float and 1 never reached.
inline float fraction_to_float(uint32_t v) { return float(v >> 8) * 0x1p-24f; }

struct SobolSeeds {
    uint32_t shuffle, scramble_x, scramble_y;
};

// Point `index` of the scrambled, shuffled sequence the seeds name: both coordinates, or the
// first alone. owen_scramble(sobol_dimension0(i)) would reverse i twice; it is the permutation of
// i itself, reversed.
struct SobolPoint {
    float x, y;
};
inline uint32_t shuffled_index(uint32_t index, const SobolSeeds& seeds) { return owen_scramble(index, seeds.shuffle); }
inline float owen_scrambled_sobol_x(uint32_t shuffled, const SobolSeeds& seeds) {
    return fraction_to_float(reverse_bits32(laine_karras_permutation(shuffled, seeds.scramble_x)));
}
// Point `index` itself (no shuffle), scrambled: where one 2D sequence is all there is to
// decorrelate, as for the pixel position alone.
inline SobolPoint owen_scrambled_sobol_unshuffled(uint32_t index, const SobolSeeds& seeds) {
    const uint32_t y = reverse_bits32(laine_karras_permutation(sobol_dimension1_reversed(index), seeds.scramble_y));
    return {owen_scrambled_sobol_x(index, seeds), fraction_to_float(y)};
}
inline SobolPoint owen_scrambled_sobol(uint32_t index, const SobolSeeds& seeds) {
    return owen_scrambled_sobol_unshuffled(shuffled_index(index, seeds), seeds);
}

}  // namespace wt
