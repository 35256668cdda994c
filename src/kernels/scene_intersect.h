#pragma once
// One ray against the whole scene: closest hit and any hit (occlusion). The scene is small
// enough (tens of primitives) that a flat loop over the SoA buffers beats a BVH.

#include "core/ray.h"
#include "core/scene.h"
#include "kernels/primitive_intersect.h"

namespace wt {

// Closest hit with t in (0, tmax).
inline Hit intersect_closest(const Scene& scene, const Ray& ray, float tmax = std::numeric_limits<float>::infinity()) {
    Hit hit;
    hit.t = tmax;
    const uint32_t triangle_count = uint32_t(scene.triangles.size());
    for (uint32_t i = 0; i < triangle_count; ++i) intersect_triangle(scene.triangles, i, ray, hit);
    for (uint32_t i = 0; i < scene.spheres.size(); ++i) intersect_sphere(scene.spheres, i, triangle_count + i, ray, hit);
    if (!hit.found()) hit.t = std::numeric_limits<float>::infinity();
    return hit;
}

// True if anything lies at t in (0, tmax); stops at the first blocker found.
inline bool intersect_any(const Scene& scene, const Ray& ray, float tmax) {
    Hit hit;
    hit.t = tmax;
    const uint32_t triangle_count = uint32_t(scene.triangles.size());
    for (uint32_t i = 0; i < triangle_count; ++i)
        if (intersect_triangle(scene.triangles, i, ray, hit)) return true;
    for (uint32_t i = 0; i < scene.spheres.size(); ++i)
        if (intersect_sphere(scene.spheres, i, triangle_count + i, ray, hit)) return true;
    return false;
}

}  // namespace wt
