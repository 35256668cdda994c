#include "kernels/isa/intersect_dispatch.h"
#include "kernels/wavefront/stages.h"

namespace wt {

void shadow_stage(const IntersectContext& context, ShadowQueue& shadows, PathTable& paths) {
    if (context.bvh)
        context.kernels->any_bvh(*context.bvh, ray_view(shadows), shadows.occluded.data());
    else
        context.kernels->any_raypacket(context.scene, ray_view(shadows), shadows.occluded.data());
    // In queue order, so each path adds its shadow rays' light in the order they were cast.
    for (std::size_t i = 0; i < shadows.count; ++i)
        if (!shadows.occluded[i]) paths.add_radiance(shadows.path[i], shadows.contribution(i));
}

}  // namespace wt
