#pragma once
// The estimator options (estimator_settings.h) as compile-time choices. The vertex code
// (path_vertex.h) and both integrators are templates over an Estimator, instantiated for every
// combination and chosen once per tile: the default estimator's code is the code there was
// before the options existed, and the others pay for their choice without a test per sample.

#include <utility>

#include <glm/vec3.hpp>

#include "core/description/estimator_settings.h"
#include "core/sampling/samplers.h"

namespace wt {

template <typename SamplerType, LightSampling kLightSampling, bool kClampsIndirect>
struct Estimator {
    using Sampler = SamplerType;
    static constexpr bool mis = kLightSampling == LightSampling::mis;
    static constexpr bool clamps_indirect = kClampsIndirect;
};

using DefaultEstimator = Estimator<StratifiedSampler, LightSampling::nee, false>;

// X(sampler, light sampling, clamps) for every estimator but the default, for explicit
// instantiations: the hot stages compile the default alone in its own translation unit, so
// g++'s inlining of it is what it was with one estimator (with all twelve in one unit it stopped
// inlining the surface and ray-offset helpers: +5 % instructions in the perf gate's render).
#define WT_FOR_EACH_OPTIONAL_ESTIMATOR(X)                                                              \
    X(IndependentSampler, nee, false) X(IndependentSampler, nee, true) X(IndependentSampler, mis, false) \
    X(IndependentSampler, mis, true) X(StratifiedSampler, nee, true) X(StratifiedSampler, mis, false)    \
    X(StratifiedSampler, mis, true) X(SobolSampler, nee, false) X(SobolSampler, nee, true)               \
    X(SobolSampler, mis, false) X(SobolSampler, mis, true)
#define WT_ESTIMATOR(sampler, light_sampling, clamps) Estimator<sampler, LightSampling::light_sampling, clamps>

// Calls f(Estimator<...>{}) with the estimator the settings name.
template <typename Sampler, typename F>
decltype(auto) with_light_sampling(const EstimatorSettings& s, F&& f) {
    const bool clamps = s.clamp_indirect > 0.0f;
    if (s.light_sampling == LightSampling::mis)
        return clamps ? f(Estimator<Sampler, LightSampling::mis, true>{}) : f(Estimator<Sampler, LightSampling::mis, false>{});
    return clamps ? f(Estimator<Sampler, LightSampling::nee, true>{}) : f(Estimator<Sampler, LightSampling::nee, false>{});
}
template <typename F>
decltype(auto) with_estimator(const EstimatorSettings& s, F&& f) {
    switch (s.sampler) {
        case SamplerKind::independent: return with_light_sampling<IndependentSampler>(s, std::forward<F>(f));
        case SamplerKind::sobol: return with_light_sampling<SobolSampler>(s, std::forward<F>(f));
        case SamplerKind::stratified: break;
    }
    return with_light_sampling<StratifiedSampler>(s, std::forward<F>(f));
}

// The firefly clamp, Cycles' "indirect light clamp" done per channel: every contribution of
// light that has scattered at two or more surfaces before reaching the camera is limited to
// `limit` in each channel. That is a light sample taken at vertex 1 or later (the camera's first
// hit is vertex 0), and emission hit at vertex 2 or later (the BSDF-sampled twin of a light
// sample at vertex 1 or later, and light seen through two or more mirror or glass bounces).
// Light seen directly, light samples at the first hit and emission found by the first hit's
// bounce are never clamped. The limit applies to the contribution as it enters the pixel
// (throughput included), per sample: a vertex's M light samples, each weighted 1/M, are
// limited to limit / M each.
inline bool is_indirect_light_sample(uint32_t bounce) { return bounce >= 1; }
inline bool is_indirect_emission(uint32_t bounce) { return bounce >= 2; }
// A NaN stays NaN, so the film still rejects and counts it.
inline glm::vec3 clamped_per_channel(const glm::vec3& c, float limit) {
    return {c.x > limit ? limit : c.x, c.y > limit ? limit : c.y, c.z > limit ? limit : c.z};
}

// Veach's power heuristic (thesis, sec. 9.2.4, beta = 2) for the strategy whose pdf times
// sample count is `mine`, against `other`.
inline float power_heuristic(float mine, float other) {
    const float a = mine * mine;
    return a / (a + other * other);
}

}  // namespace wt
