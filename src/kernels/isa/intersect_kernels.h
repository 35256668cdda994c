#pragma once
// The SIMD intersection kernels, compiled once per instruction set and picked at run time.
// Only plain declarations here: this header is included by the per-ISA translation units.

#include <cstdint>

#include "kernels/accel/bvh_view.h"
#include "kernels/isa/isa.h"
#include "kernels/primitives/soa_views.h"

namespace wt {


// Two ways to put SIMD lanes to work on a flat primitive list:
//   ray packet  - N rays from the queue against one primitive at a time (primitive broadcast)
//   prim packet - one ray against N primitives at a time (SoA primitive loads, then a
//                 horizontal reduction for the closest)
// and one ray at a time through a BVH (kernels/accel/bvh.h), whose leaves are prim packets.
// All give the same answers; bench_intersect measures which is faster per query and scene.
struct IntersectKernels {
    Isa isa;
    int width;
    void (*closest_raypacket)(const SceneView&, const RayView&, const HitView&);
    void (*closest_primpacket)(const SceneView&, const RayView&, const HitView&);
    // occluded[i] = 1 if anything lies at t in (0, tmax[i]) along ray i, else 0.
    void (*any_raypacket)(const SceneView&, const RayView&, uint8_t* occluded);
    void (*any_primpacket)(const SceneView&, const RayView&, uint8_t* occluded);
    void (*closest_bvh)(const BvhView&, const RayView&, const HitView&);
    void (*any_bvh)(const BvhView&, const RayView&, uint8_t* occluded);
    // N rays at a time through the BVH: for coherent rays (camera rays), same answers.
    void (*closest_bvh_packets)(const BvhView&, const RayView&, const HitView&);
    void (*any_bvh_packets)(const BvhView&, const RayView&, uint8_t* occluded);
};

// Each ISA has one kernel set per accuracy combination: (triangle test, sphere test), indexed
// 2 * triangle + sphere (see kernel_variant() in intersect_dispatch.cpp).
constexpr int kKernelVariantCount = 4;

// Defined in intersect_<isa>.cpp, each compiled with its own target flags.
extern const IntersectKernels kIntersectScalar[kKernelVariantCount];
extern const IntersectKernels kIntersectSse4[kKernelVariantCount];
extern const IntersectKernels kIntersectAvx2[kKernelVariantCount];
extern const IntersectKernels kIntersectAvx512[kKernelVariantCount];

}  // namespace wt
