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

// How a light sample picks one of the emissive triangles (core/lights/emitter_selection.h).
// Light paths (light tracing, photons) start by area whichever is chosen.
enum class LightSelection : uint8_t {
    // power where the scene has many emitters whose radiance differs, else area (so a scene with
    // few lights keeps its image bits): chosen_light_selection(), measured in bench/README.md
    automatic,
    area,   // in proportion to area: pdf 1 / total area on every light, whatever it emits
    power,  // in proportion to power (area times luminance of the emission)
    bvh,    // by a light tree, in proportion to each node's importance to the shading point
};

// Who finds caustic paths: a diffuse surface lit by the lights through one or more mirror or
// glass bounces (diffuse -> specular... -> light), seen directly (camera -> diffuse) or itself
// seen through a mirror or glass (camera -> specular... -> diffuse).
enum class CausticPaths : uint8_t {
    path,           // the camera path's BSDF sample, which must hit the light by chance
    light_tracing,  // paths from the lights through the specular bounces, connected to the camera
    // light_tracing, and the same light paths' diffuse vertices as photons: a camera path whose
    // first hit is a mirror or glass gathers them at its first diffuse vertex (kernels/photons)
    photons,
};

// The largest photon_radius accepted: its square, which the lookups compare distances with, stays
// a finite float (1e36 < 3.4e38).
constexpr float kPhotonRadiusMax = 1e18f;

struct EstimatorSettings {
    SamplerKind sampler = SamplerKind::stratified;
    LightSampling light_sampling = LightSampling::nee;
    // Per-channel upper bound on each indirect contribution (see clamp_indirect() in
    // core/path/estimator.h for exactly which); 0 means off.
    float clamp_indirect = 0.0f;
    // Photons (light tracing, and its light paths' photons for the caustics seen through a mirror
    // or glass) wherever a scene can have caustics (a light and a mirror or glass surface); a
    // scene without them runs the camera paths alone either way. Why: README, "Caustics seen
    // through a mirror: photons" (the most efficient of the three on every scene measured, its
    // bias below its noise).
    CausticPaths caustics = CausticPaths::photons;
    // After the fields a positional initialiser names ({sampler, light_sampling, clamp,
    // caustics}), so they keep their meaning, and in caustics' padding, so the settings every
    // stage copies keep their size.
    LightSelection light_selection = LightSelection::automatic;
    // With light tracing, light paths per pixel of the image and per sample: the light-tracing
    // work per sample is this times width x height paths.
    float light_paths_per_pixel = 1.0f;
    // With photons, the radius r_0 of sample 0's photon lookups, in scene units (later samples'
    // shrink from it, kernels/photons/photon_radius.h); 0: automatic, from the camera's pixel
    // footprint at the scene's distance.
    float photon_radius = 0.0f;
};

const char* name_of(SamplerKind);
const char* name_of(LightSampling);
const char* name_of(CausticPaths);
const char* name_of(LightSelection);
std::optional<CausticPaths> parse_caustic_paths(const std::string&);
std::optional<SamplerKind> parse_sampler(const std::string&);
std::optional<LightSampling> parse_light_sampling(const std::string&);
std::optional<LightSelection> parse_light_selection(const std::string&);

}  // namespace wt
