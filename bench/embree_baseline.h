#pragma once
// Embree 3 as a yardstick for our kernels: the same scene and the same rays through Intel's
// BVH kernels, written to the same outputs so bench_intersect reports them the same way.
// Built only when CMake finds Embree (WAVETRACE_HAVE_EMBREE); nothing else depends on it, and
// this header does not include Embree's, so only embree_baseline.cpp needs them.

#include <cstdint>
#include <memory>

#include "core/scene/scene.h"
#include "kernels/primitives/soa_views.h"

namespace wt::bench {

// Which Embree entry point traces the rays.
enum class EmbreeApi {
    single,    // rtcIntersect1 / rtcOccluded1, one ray at a time
    packet8,   // rtcIntersect8 / rtcOccluded8, packets of 8 consecutive rays
    packet16,  // rtcIntersect16 / rtcOccluded16, packets of 16
};

class EmbreeBaseline {
public:
    // Triangles become one RTC_GEOMETRY_TYPE_TRIANGLE geometry (vertices v0, v0 + e1, v0 + e2
    // from the scene's SoA, so Embree sees the triangles our kernels see), spheres one
    // RTC_GEOMETRY_TYPE_SPHERE_POINT geometry. The device builds on one thread.
    explicit EmbreeBaseline(const Scene& scene);
    ~EmbreeBaseline();
    EmbreeBaseline(const EmbreeBaseline&) = delete;
    EmbreeBaseline& operator=(const EmbreeBaseline&) = delete;

    // The contracts of IntersectKernels: closest hit with prim in our primitive index space
    // (kNoHit and t = +inf for a miss); occluded[i] = 1 if anything blocks ray i before its
    // tmax. Rays run from t = 0. `coherent` tells Embree the rays are coherent (primary rays),
    // which it may use to pick its packet traversal.
    void closest(EmbreeApi api, const RayView& rays, const HitView& hits, bool coherent) const;
    void any(EmbreeApi api, const RayView& rays, uint8_t* occluded, bool coherent) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Embree's BVH build, for timing beside ours: an Embree device with `threads` build threads
// ("threads=N"), on which build() makes the scene as EmbreeBaseline does: rtcNewScene, the
// geometries (our primitives copied into Embree's buffers) and rtcCommitScene. release()
// frees the last one built (build() and the destructor call it too), so a benchmark can keep
// the freeing out of its timing.
class EmbreeSceneBuilder {
public:
    explicit EmbreeSceneBuilder(int threads);
    ~EmbreeSceneBuilder();
    EmbreeSceneBuilder(const EmbreeSceneBuilder&) = delete;
    EmbreeSceneBuilder& operator=(const EmbreeSceneBuilder&) = delete;

    void build(const Scene& scene);
    void release();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace wt::bench
