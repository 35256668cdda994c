#include "kernels/isa/intersect_dispatch.h"
#include "kernels/wavefront/stages.h"

namespace wt {

// Without a BVH, rays of a queue go in packets of N against one primitive at a time: on the
// flat primitive list of a small scene this beat one ray against N primitives (bench/README.md).
// Through a BVH, camera rays go in packets (they enter the same nodes, so a packet shares each
// node's fetch and box test; bench/README.md has the ratio), the rest one at a time.
void intersect_closest_stage(const IntersectContext& context, const RayQueue& rays, HitQueue& hits, bool coherent) {
    if (context.bvh)
        (coherent ? context.kernels->closest_bvh_packets : context.kernels->closest_bvh)(*context.bvh, ray_view(rays), hit_view(hits));
    else
        context.kernels->closest_raypacket(context.scene, ray_view(rays), hit_view(hits));
}

}  // namespace wt
