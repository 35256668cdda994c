#pragma once
// One ray through the BVH with the scalar kernels, for code that traces a ray at a time (the
// reference integrator, --debug-sample). The same bits as intersect_closest / intersect_any in
// scene_intersect.h, which loop over every primitive.

#include <limits>

#include "core/base/accuracy.h"
#include "core/base/ray.h"
#include "kernels/accel/bvh_view.h"

namespace wt {

Hit bvh_intersect_closest(const BvhView& bvh, const AccuracySettings& accuracy, const Ray& ray,
                          float tmax = std::numeric_limits<float>::infinity());
bool bvh_intersect_any(const BvhView& bvh, const AccuracySettings& accuracy, const Ray& ray, float tmax);

}  // namespace wt
