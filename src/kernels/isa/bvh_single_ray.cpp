#include "kernels/isa/bvh_single_ray.h"

#include "kernels/isa/intersect_dispatch.h"

namespace wt {
namespace {
RayView one_ray(const Ray& ray, const float* tmax) {
    return {&ray.origin.x, &ray.origin.y, &ray.origin.z, &ray.direction.x, &ray.direction.y, &ray.direction.z, tmax, 1u};
}
}  // namespace

Hit bvh_intersect_closest(const BvhView& bvh, const AccuracySettings& accuracy, const Ray& ray, float tmax) {
    Hit hit;
    intersect_kernels(Isa::scalar, accuracy).closest_bvh(bvh, one_ray(ray, &tmax), {&hit.t, &hit.u, &hit.v, &hit.prim});
    return hit;
}

bool bvh_intersect_any(const BvhView& bvh, const AccuracySettings& accuracy, const Ray& ray, float tmax) {
    uint8_t occluded = 0;
    intersect_kernels(Isa::scalar, accuracy).any_bvh(bvh, one_ray(ray, &tmax), &occluded);
    return occluded != 0;
}

}  // namespace wt
