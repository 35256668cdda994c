#pragma once
// What one batch of photon maps (photon_maps.h) is expected to hold, for the memory estimate
// (kernels/memory_estimate.h): a batch holds the photons of whole samples, so at least one
// sample's light paths, however small --photon-batch-paths is.
//
// A light path goes on past its first vertex only from a mirror or glass, and leaves a photon at
// each diffuse vertex from its second on (light_path.cpp), so the count follows the share of the
// scene that is specular and how long the scene keeps the paths alive after: every vertex up to
// the first Russian roulette bounce, then each further one with about the surfaces' reflectance
// q (the roulette keeps a path with its throughput's largest channel, capped at 0.95). Both are
// the scene's averages over its surface area: the result is an expectation, not a bound (the
// render's summary prints the count beside it).

#include <cstdint>

#include "core/scene/scene.h"

namespace wt {

// The light paths per photon batch: whole samples of light_paths_per_sample each.
uint64_t photon_batch_light_paths(uint64_t batch_paths, uint64_t light_paths_per_sample);

// Expected photons per light path (see above).
double expected_photons_per_light_path(const Scene& scene);

// Bytes per photon at a batch's peak: its list entry (with the list's growth slack) and its copy,
// index and bucket in the sample's grid, while every grid of the batch is built.
double photon_peak_bytes();

// Expected bytes of one batch's photon maps at their peak.
double photon_batch_bytes(const Scene& scene, uint64_t batch_paths);

}  // namespace wt
