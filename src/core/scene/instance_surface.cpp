#include <glm/geometric.hpp>

#include "core/scene/scene.h"

// A hit on an instanced triangle as the shade stage needs it (scene.h's surface_at for the
// scene's own primitives).

namespace wt {

SurfacePoint instance_surface_at(const Scene& scene, const Hit& hit) {
    const Instance& k = scene.instances.instance_of(hit.prim);
    const InstancedMesh& mesh = scene.instances.meshes[k.mesh];
    const TriangleSoA& t = mesh.triangles;
    const uint32_t i = hit.prim - k.first_id;
    SurfacePoint s;
    // In object space first, as a flat triangle's (scene.h), then placed.
    const TriangleSoA::Corner c = t.corner(i);
    const glm::vec3 local = c.v0 + hit.u * c.e1 + hit.v * c.e2;
    glm::vec3 local_error = triangle_point_error(c.v0, c.e1, c.e2, hit.u, hit.v);
    if (scene.settings.accuracy.triangles == TriangleTest::watertight) local_error = with_watertight_floor(local_error);
    s.position = k.to_world.point(local);
    // The placement's rounding (pbrt-v4's transformed-point bound), and the rounding the inverse
    // will add when a ray leaving here is taken back into object space, seen in world space:
    // the offset must clear the surface as the instance's traversal will see the origin.
    const glm::vec3 back_error = k.to_object.point_error(s.position, glm::vec3(0.0f));
    s.error = k.to_world.point_error(local, local_error) + (1.0f + rounding_gamma(3)) * k.to_world.magnitude_times(back_error);
    // Normals by the inverse transpose. A mirroring placement needs no sign: its world
    // triangles are wound the other way round (place_mesh.h), so the normal keeps its side.
    const glm::vec3 local_normal = TriangleSoA::unit_normal(c.e1, c.e2);
    s.normal = glm::normalize(k.to_object.transposed_vector(local_normal));
    s.shading_normal = s.normal;
    s.smooth = false;
    glm::vec3 vertex[3];
    if (!mesh.shading_normals.empty() && mesh.shading_normals.vertex_normals(t, i, vertex)) {
        // Each vertex normal placed and renormalised before the blend, as a flattened mesh's
        // are (place_mesh.h): under a non-uniform scale, blending first would weight them
        // differently.
        for (glm::vec3& n : vertex) n = glm::normalize(k.to_object.transposed_vector(n));
        s.shading_normal = blend_normals(vertex[0], vertex[1], vertex[2], hit.u, hit.v, s.normal);
        s.smooth = s.shading_normal != s.normal;
    }
    s.material = t.material[i];
    return s;
}

}  // namespace wt
