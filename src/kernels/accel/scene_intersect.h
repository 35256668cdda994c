#pragma once
// One ray against the whole scene: closest hit and any hit (occlusion). The scene is small
// enough (tens of primitives) that a flat loop over the SoA buffers beats a BVH.

#include "core/base/ray.h"
#include "core/scene/scene.h"
#include "kernels/primitives/primitive_intersect.h"

namespace wt {

namespace detail {
// Visits every primitive with the tests the scene's accuracy settings choose; visit returns
// true to stop early (any-hit).
template <typename Visit>
inline void for_each_primitive_hit(const Scene& scene, const Ray& ray, Hit& hit, Visit&& stop_at) {
    const AccuracySettings& accuracy = scene.settings.accuracy;
    const uint32_t triangle_count = uint32_t(scene.triangles.size());
    if (accuracy.triangles == TriangleTest::watertight) {
        const WatertightRay w = watertight_ray(ray.direction);
        for (uint32_t i = 0; i < triangle_count; ++i)
            if (intersect_triangle_watertight(scene.triangles, i, ray, w, hit) && stop_at()) return;
    } else {
        for (uint32_t i = 0; i < triangle_count; ++i)
            if (intersect_triangle(scene.triangles, i, ray, hit) && stop_at()) return;
    }
    const bool cancellation_free = accuracy.spheres == SphereTest::cancellation_free;
    for (uint32_t i = 0; i < scene.spheres.size(); ++i) {
        const bool found = cancellation_free
                               ? intersect_sphere_cancellation_free(scene.spheres, i, triangle_count + i, ray, hit)
                               : intersect_sphere(scene.spheres, i, triangle_count + i, ray, hit);
        if (found && stop_at()) return;
    }
}
}  // namespace detail

// Closest hit with t in (0, tmax).
inline Hit intersect_closest(const Scene& scene, const Ray& ray, float tmax = std::numeric_limits<float>::infinity()) {
    Hit hit;
    hit.t = tmax;
    detail::for_each_primitive_hit(scene, ray, hit, [] { return false; });
    if (!hit.found()) hit.t = std::numeric_limits<float>::infinity();
    return hit;
}

// True if anything lies at t in (0, tmax); stops at the first blocker found.
inline bool intersect_any(const Scene& scene, const Ray& ray, float tmax) {
    Hit hit;
    hit.t = tmax;
    bool blocked = false;
    detail::for_each_primitive_hit(scene, ray, hit, [&] { return blocked = true; });
    return blocked;
}

}  // namespace wt
