#pragma once
// The photon lookups' radius, per sample index: progressive photon mapping the way of Knaus and
// Zwicker ("Progressive photon mapping: a probabilistic approach", ACM TOG 30(3), 2011). Sample
// s is one independent photon-mapping estimate with its own photons (the light paths of sample
// s) and radius r_s; the pixel averages the samples. With r_{s+1}^2 = r_s^2 (s + 1 + alpha) /
// (s + 2), i.e. their r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1) with i = s + 1, the average's
// variance and bias both vanish as the samples grow (their sec. 4, for 0 < alpha < 1): the
// estimate is consistent.
//
// r_s is a pure function of (r_0, s), never state carried from sample to sample: a pixel's
// samples are the same whatever range, pass, thread, rank or resumed checkpoint renders them.

#include <cstdint>

#include "core/scene/scene.h"

namespace wt {

// Knaus and Zwicker's alpha: the share of each new sample's radius reduction kept (their
// experiments, and pbrt-v4's SPPM, use 2/3).
constexpr double kPhotonRadiusAlpha = 2.0 / 3.0;

// r_0: the scene's photon_radius, or when it is 0 the automatic one (photon_radius.cpp), no
// larger than the scene's bounding-box diagonal (a disk larger than the scene holds every photon
// a smaller one would; only its area grows).
double initial_photon_radius(const Scene& scene);

// r_s^2 from r_0^2, in double and in a fixed order of operations: the same bits for the same
// arguments on any machine. Remembers where it was, so that ascending sample indices cost O(1)
// each; the value never depends on that memory (it restarts from s = 0 when asked for less).
class PhotonRadiusSchedule {
public:
    explicit PhotonRadiusSchedule(double initial_radius)
        : initial_squared_(initial_radius * initial_radius), squared_(initial_squared_) {}
    double squared(uint32_t sample);

private:
    double initial_squared_;
    uint32_t sample_ = 0;  // squared_ is r^2 of this sample
    double squared_;
};

}  // namespace wt
