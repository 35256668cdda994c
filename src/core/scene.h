#pragma once
// The scene as the renderer sees it: SoA geometry, materials, the light table and the camera.
// Only what the description contains is built; an empty sphere buffer means the intersect
// stage runs no sphere code at all.

#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "core/camera.h"
#include "core/geometry_soa.h"
#include "core/light_table.h"
#include "core/ray.h"
#include "core/ray_offset.h"
#include "core/scene_description.h"

namespace wt {

struct Scene {
    RenderSettings settings;
    Camera camera;
    std::vector<Material> materials;
    TriangleSoA triangles;
    SphereSoA spheres;
    LightTable lights;

    uint32_t primitive_count() const { return uint32_t(triangles.size() + spheres.size()); }
};

// Validates nothing: descriptions come from the loader (which validates) or from code.
Scene build_scene(const SceneDescription& description);

// What the shade stage needs to know about a hit.
struct SurfacePoint {
    glm::vec3 position;
    glm::vec3 error;   // bound on the rounding error of position, for offset_ray_origin()
    glm::vec3 normal;  // geometric; winding for triangles, outward for spheres
    uint32_t material;
};

inline SurfacePoint surface_at(const Scene& scene, const Ray& ray, const Hit& hit) {
    SurfacePoint s;
    const uint32_t triangle_count = uint32_t(scene.triangles.size());
    if (hit.prim < triangle_count) {
        const TriangleSoA& t = scene.triangles;
        // From barycentrics rather than o + t*d: its error does not grow with the hit distance,
        // which is what the ulp-based ray offset assumes.
        s.position = t.vertex0(hit.prim) + hit.u * t.edge1(hit.prim) + hit.v * t.edge2(hit.prim);
        s.error = triangle_point_error(t.vertex0(hit.prim), t.edge1(hit.prim), t.edge2(hit.prim), hit.u, hit.v);
        s.normal = t.normal(hit.prim);
        s.material = t.material[hit.prim];
    } else {
        const uint32_t i = hit.prim - triangle_count;
        const glm::vec3 c = scene.spheres.center(i);
        const float r = scene.spheres.radius[i];
        s.normal = glm::normalize(ray.origin + hit.t * ray.direction - c);
        // Projected back onto the sphere, for the same reason.
        s.position = c + r * s.normal;
        s.error = sphere_point_error(c, r, s.normal);
        s.material = scene.spheres.material[i];
    }
    return s;
}

}  // namespace wt
