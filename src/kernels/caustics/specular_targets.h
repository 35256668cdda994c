#pragma once
// The primitives a light path's first ray must hit for the path to add anything to the image.
// LightPathTracer::at_vertex ends a path at its first diffuse or rough vertex (that light is
// direct light, which the camera paths' light samples estimate), so only a path whose first hit
// is a mirror, glass or smooth metal goes on to a splat or a photon. In a room most first rays
// hit a wall: a ray that misses every specular primitive is not traced at all, and the image
// keeps its bits (each path's random numbers are its own, the film's sums are exact, and the
// photons keep their order).
//
// Exact, not a bound: the same primitive tests the kernels' bits follow (primitive_intersect.h),
// with no far limit, so the primitive a closest hit would find is found here too (an alpha test
// can only take hits away). The wavefront light pass asks for a whole batch of first rays at
// once: view() is the targets alone as a flat scene, for the any-hit kernels, whose answers are
// may_hit's bit for bit (tests/specular_targets_test.cpp). Kept only when the specular primitives are few (one flat loop a
// path); with many, or with instanced meshes that have a specular material, every first ray is
// traced.

#include <cstdint>
#include <optional>
#include <vector>

#include "core/base/ray.h"
#include "core/scene/scene.h"
#include "kernels/primitives/soa_views.h"
#include "kernels/primitives/triangle_rows.h"

namespace wt {

class SpecularTargets {
public:
    // More would cost a path more than the tracing it saves.
    static constexpr std::size_t kMostPrimitives = 32;

    // None if the scene has too many specular primitives, or instanced specular ones.
    static std::optional<SpecularTargets> of(const Scene& scene);
    // Whether `ray` meets some specular primitive at any distance.
    bool may_hit(const Ray& ray) const;
    // The targets as a scene of their own: a ray is occluded in it (any_raypacket, t in (0, tmax)
    // with tmax infinite) exactly when may_hit says yes. Valid while this object lives, unmoved.
    SceneView view() const;

private:
    const Scene* scene_ = nullptr;
    std::vector<uint32_t> triangles_, spheres_;  // indices into the scene's TriangleSoA and SphereSoA
    TriangleRows triangle_rows_;                 // those triangles' rows, in that order
    AlignedVector<float> sphere_x_, sphere_y_, sphere_z_, sphere_radius_;  // and those spheres'
};

}  // namespace wt
