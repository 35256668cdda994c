#pragma once
// The switches that change the Monte Carlo estimator itself, not the geometry: where the random
// numbers come from, how direct light is sampled, and whether bright indirect samples are
// clamped. The defaults are the classic estimator; the alternatives trade time, variance
// and (the clamp) bias, measured in the README ("Estimator options").

#include <cstdint>
#include <optional>
#include <string>

namespace wt {

enum class SamplerKind : uint8_t {
    independent,  // every dimension a hash of (seed, pixel, sample, bounce, dimension)
    stratified,   // the pixel position from a per-pixel scrambled (0, 2)-sequence, the other dimensions independent
    sobol,        // Owen-scrambled Sobol' points, padded per pair of dimensions (Burley 2020)
};

enum class LightSampling : uint8_t {
    nee,  // light samples only; emission hit by a diffuse bounce is not counted
    mis,  // light samples and the BSDF-sampled direction both count, power heuristic (Veach 1997)
};

struct EstimatorSettings {
    SamplerKind sampler = SamplerKind::stratified;
    LightSampling light_sampling = LightSampling::nee;
    // Per-channel upper bound on each indirect contribution (see clamp_indirect() in
    // core/estimator.h for exactly which); 0 means off.
    float clamp_indirect = 0.0f;
};

const char* name_of(SamplerKind);
const char* name_of(LightSampling);
std::optional<SamplerKind> parse_sampler(const std::string&);
std::optional<LightSampling> parse_light_sampling(const std::string&);

}  // namespace wt
