#pragma once
// The first rays of light paths that start at area lights, N at a time: area_light_ray
// (kernels/caustics/light_path.cpp) over a LightPointQueue, the direction cosine-weighted about
// the light's normal, the origin moved off the light. One generic loop, instantiated per ISA at
// its widest vector (kernels/isa/shade_<isa>.cpp) and at width 1 for the scalar kernels.
//
// Bit for bit what the scalar code computes, lane by lane, with the diffuse continuation's
// helpers (the same sample_cosine_hemisphere, Frame and normalize): tests/shade_kernels_test.cpp
// holds every ISA's rays to LightPathTracer::start.

#include <cstdint>
#include <limits>

#include "kernels/queues/light_point_queue.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/shading/diffuse_continuation.h"
#include "kernels/shading/lanes.h"

namespace wt::shading {
inline namespace WT_SIMD_ISA {

// Appends to `out` the ray of every entry of `q` whose direction is strictly above the light
// (one lost to rounding at the horizon starts no path), in the queue's order, with an infinite
// tmax, a unit contribution (the path's weight so far) and the entry's slot.
template <int N>
void aim_area_light_rays(const LightPointQueue& q, ShadowQueue& out) {
    alignas(64) float lanes[6][N];  // origin and direction of each lane
    for (std::size_t i = 0; i < q.count; i += N) {
        const Lanes3<N> normal = load3<N>(q.nx, q.ny, q.nz, i);
        const Lanes3<N> direction = to_world_normalized<N>(
            normal, sample_cosine_hemisphere<N>(vfloat<N>::load(q.u0.data() + i), vfloat<N>::load(q.u1.data() + i)));
        const vbool<N> above = dot(direction, normal) > 0.0f;
        const Lanes3<N> origin = offset_ray_origin<N>(load3<N>(q.px, q.py, q.pz, i), load3<N>(q.ex, q.ey, q.ez, i), normal);
        const vfloat<N> values[6] = {origin.x, origin.y, origin.z, direction.x, direction.y, direction.z};
        for (int k = 0; k < 6; ++k) vfloat<N>::store(lanes[k], values[k]);
        for (uint32_t pushed = lanes_below(above, q.count - i); pushed != 0; pushed &= pushed - 1) {
            const int lane = __builtin_ctz(pushed);
            const std::size_t o = out.count++;
            out.ox[o] = lanes[0][lane], out.oy[o] = lanes[1][lane], out.oz[o] = lanes[2][lane];
            out.dx[o] = lanes[3][lane], out.dy[o] = lanes[4][lane], out.dz[o] = lanes[5][lane];
            out.tmax[o] = std::numeric_limits<float>::infinity();
            out.contribution_r[o] = 1.0f, out.contribution_g[o] = 1.0f, out.contribution_b[o] = 1.0f;
            out.path[o] = q.path[i + lane];
        }
    }
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::shading
