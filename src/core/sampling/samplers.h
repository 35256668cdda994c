#pragma once
// The three samplers behind the `sampler` setting, one interface. A sampler is made for one
// path vertex from the path's seed and the bounce, and gives the vertex's random numbers by the
// dimensions of rng.h's `dim` namespace: pair(d) for dimensions d and d + 1 (d even) and
// operator()(d) for one. At the camera, pixel_offset() places the sample in its pixel and, for
// a thin lens only, lens_position() on the lens: a 2D pattern of its own, apart from every
// vertex's dimensions (kLensBounce), so the lens is as well distributed as the pixel.
// kCheapDraws says whether a draw whose value will not be read is worth a test to skip.
//
// Every value is a pure function of (seed, pixel, sample, bounce, dimension), for all three, so
// any sample replays alone and images do not depend on threads or batching. The integrators
// are instantiated per sampler (core/path/estimator.h): the default costs what it did before there
// was a choice.

#include <cstdint>

#include <glm/vec2.hpp>

#include "core/sampling/rng.h"
#include "core/sampling/sampling.h"
#include "core/sampling/sobol.h"

namespace wt {

// What one camera path's samplers are made from: a key hashed from (seed, pixel, sample) or,
// for Sobol', from (seed, pixel), once when the path starts; and the sample's index in its pixel.
struct PathSeed {
    uint64_t key;
    uint32_t sample;
};

// The lens sample is drawn as if at a bounce no path reaches (max_bounces is at most 1024): its
// hashes and, for Sobol', its scrambling and shuffling seeds are apart from every vertex's.
constexpr uint32_t kLensBounce = 0xffffffffu;

// Every dimension a hash (VertexRandom), the pixel position too.
class IndependentSampler : public VertexRandom {
public:
    static constexpr bool kCheapDraws = true;  // one hash: never worth a test to skip a draw
    static uint64_t key_of(uint64_t seed, uint32_t pixel, uint32_t sample) { return path_key(seed, pixel, sample); }
    IndependentSampler(const PathSeed& path, uint32_t bounce, uint32_t /*shadow_rays*/) : VertexRandom(path.key, bounce) {}

    glm::vec2 pixel_offset(uint64_t /*seed*/, uint32_t /*pixel*/, uint32_t /*sample*/) const {
        const UniformPair p = pair(dim::camera_x);
        return {p.first, p.second};
    }
    static glm::vec2 lens_position(const PathSeed& path, uint64_t /*seed*/, uint32_t /*pixel*/) {
        const UniformPair p = VertexRandom(path.key, kLensBounce).pair(dim::camera_x);
        return {p.first, p.second};
    }
};

// The pixel position stratified, the other dimensions independent (VertexRandom). Sample s of
// a pixel sits at point s of an Owen-scrambled (0, 2)-sequence (sobol.h) scrambled for that
// pixel: every prefix of 2^m samples has one sample in each of the 2^m elementary intervals of
// the pixel, and every sample is uniform over the pixel on its own. So the position depends on
// the sample's index only, never on how many samples the render takes, and a render stopped
// early (a time limit, Ctrl-C, any pass boundary) is an unbiased image of the samples it has;
// resuming with more spp gives the same samples an uninterrupted render of that spp takes.
// (A k x k jittered grid sized from the spp, visited in scanline order, has neither property:
// the first quarter of its samples all lie in the top quarter of the pixel.)
class StratifiedSampler : public VertexRandom {
public:
    static constexpr bool kCheapDraws = true;  // hashes but for the pixel position
    static uint64_t key_of(uint64_t seed, uint32_t pixel, uint32_t sample) { return path_key(seed, pixel, sample); }
    StratifiedSampler(const PathSeed& path, uint32_t bounce, uint32_t /*shadow_rays*/) : VertexRandom(path.key, bounce) {}

    glm::vec2 pixel_offset(uint64_t seed, uint32_t pixel, uint32_t sample) const {
        const uint64_t h = mix64(mix64(seed ^ kStrataSalt) + uint64_t(pixel) * kGoldenGamma);
        const SobolPoint p = owen_scrambled_sobol_unshuffled(sample, {0u, uint32_t(h), uint32_t(h >> 32)});
        return {p.x, p.y};
    }
    // The lens stratified as the pixel is, by a (0, 2)-sequence of its own, shuffled (sobol.h): the
    // unshuffled one would pair the pixel's point s with the lens's point s, the same net twice.
    static glm::vec2 lens_position(const PathSeed& path, uint64_t seed, uint32_t pixel) {
        const uint64_t h = mix64(mix64(seed ^ kLensSalt) + uint64_t(pixel) * kGoldenGamma);
        const SobolPoint p = owen_scrambled_sobol(path.sample, {uint32_t(mix64(h)), uint32_t(h), uint32_t(h >> 32)});
        return {p.x, p.y};
    }

private:
    static constexpr uint64_t kStrataSalt = 0x57a7a5a17ULL;  // keeps these seeds apart from the other keys
    static constexpr uint64_t kLensSalt = 0x1e45a17ULL;
};

// Owen-scrambled Sobol' points (sobol.h), padded: each pair of dimensions of each bounce is its
// own 2D sequence, shuffled and scrambled by seeds hashed from (seed, pixel, bounce, pair), so
// no two pairs correlate, while within a pair a pixel's samples are stratified as a (0, 2)-net.
// A single dimension is one coordinate of its pair's point. The light dimensions of the
// `shadow_rays` light samples of one vertex are one sequence indexed sample * shadow_rays + j,
// so all the pixel's light samples at that bounce are stratified together.
class SobolSampler {
public:
    static constexpr bool kCheapDraws = false;  // a point costs ten hashes: skip the ones not read
    static uint64_t key_of(uint64_t seed, uint32_t pixel, uint32_t /*sample*/) {
        return mix64(mix64(seed ^ kSobolSalt) + uint64_t(pixel) * kGoldenGamma);
    }
    SobolSampler(const PathSeed& path, uint32_t bounce, uint32_t shadow_rays)
        : base_(path.key + (uint64_t(bounce) << 32) * kGoldenGamma), sample_(path.sample), shadow_rays_(shadow_rays) {}

    glm::vec2 pixel_offset(uint64_t /*seed*/, uint32_t /*pixel*/, uint32_t /*sample*/) const {
        const UniformPair p = pair(dim::camera_x);
        return {p.first, p.second};
    }
    // Its own padded 2D sequence: pad 0 of the lens's bounce.
    static glm::vec2 lens_position(const PathSeed& path, uint64_t /*seed*/, uint32_t /*pixel*/) {
        const UniformPair p = SobolSampler(path, kLensBounce, 1).pair(dim::camera_x);
        return {p.first, p.second};
    }

    UniformPair pair(uint32_t dimension) const {
        const Pad pad = pad_of(dimension);
        const SobolPoint p = owen_scrambled_sobol(pad.index, seeds(pad.number, true));
        return {p.x, p.y};
    }
    float operator()(uint32_t dimension) const {
        if (dimension & 1u) return pair(dimension - 1).second;
        const Pad pad = pad_of(dimension);
        const SobolSeeds s = seeds(pad.number, false);
        return owen_scrambled_sobol_x(shuffled_index(pad.index, s), s);
    }

private:
    static constexpr uint64_t kSobolSalt = 0x50b01d5a17ULL;  // keeps its keys apart from path_key's

    struct Pad {
        uint32_t number;  // which 2D sequence: the first of its dimensions, halved
        uint32_t index;   // the point's index in it
    };
    Pad pad_of(uint32_t dimension) const {
        if (dimension < dim::light_first) return {dimension >> 1, sample_};
        const uint32_t offset = dimension - dim::light_first;
        return {(dim::light_first + offset % dim::per_shadow_ray) >> 1, sample_ * shadow_rays_ + offset / dim::per_shadow_ray};
    }
    // The y seed needs a second hash; a single dimension does without it.
    SobolSeeds seeds(uint32_t pad, bool with_y) const {
        const uint64_t h = mix64(base_ + uint64_t(pad) * kGoldenGamma);
        return {uint32_t(h), uint32_t(h >> 32), with_y ? uint32_t(mix64(h)) : 0u};
    }

    uint64_t base_;
    uint32_t sample_, shadow_rays_;
};

}  // namespace wt
