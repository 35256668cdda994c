#include "core/instances/scene_instances.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/instances/build_instances.h"
#include "core/scene.h"

namespace wt {

const Instance& SceneInstances::instance_of(uint32_t prim) const {
    const auto after = std::upper_bound(instances.begin(), instances.end(), prim,
                                        [](uint32_t p, const Instance& k) { return p < k.first_id; });
    return *(after - 1);
}

SurfacePoint instance_surface_at(const Scene& scene, const Hit& hit) {
    const Instance& k = scene.instances.instance_of(hit.prim);
    const InstancedMesh& mesh = scene.instances.meshes[k.mesh];
    const TriangleSoA& t = mesh.triangles;
    const uint32_t i = hit.prim - k.first_id;
    SurfacePoint s;
    // In object space first, as a flat triangle's (scene.h), then placed.
    const glm::vec3 local = t.vertex0(i) + hit.u * t.edge1(i) + hit.v * t.edge2(i);
    glm::vec3 local_error = triangle_point_error(t.vertex0(i), t.edge1(i), t.edge2(i), hit.u, hit.v);
    if (scene.settings.accuracy.triangles == TriangleTest::watertight) local_error = with_watertight_floor(local_error);
    s.position = k.to_world.point(local);
    // The placement's rounding (pbrt-v4's transformed-point bound), and the rounding the inverse
    // will add when a ray leaving here is taken back into object space, seen in world space:
    // the offset must clear the surface as the instance's traversal will see the origin.
    const glm::vec3 back_error = k.to_object.point_error(s.position, glm::vec3(0.0f));
    s.error = k.to_world.point_error(local, local_error) + (1.0f + rounding_gamma(3)) * k.to_world.magnitude_times(back_error);
    // Normals by the inverse transpose. A mirroring placement needs no sign: its world
    // triangles are wound the other way round (place_mesh.h), so the normal keeps its side.
    const glm::vec3 local_normal = t.normal(i);
    s.normal = glm::normalize(k.to_object.transposed_vector(local_normal));
    s.shading_normal = s.normal;
    s.smooth = false;
    glm::vec3 vertex[3];
    if (!mesh.shading_normals.empty() && mesh.shading_normals.vertex_normals(i, vertex)) {
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

std::string instance_transform_problem(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return "is not finite";
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0) return "is not affine (last row not 0 0 0 1)";
    const glm::dmat3 linear(m);
    const double scale = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    const double det = glm::determinant(linear);
    if (!(std::fabs(det) > 1e-12 * scale)) return "is singular (determinant " + std::to_string(det) + ")";
    // Both directions must be finite in float, or the ray taken into object space overflows.
    const glm::dmat4 inverse = glm::inverse(m);
    for (const glm::dmat4* a : {&m, &inverse})
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 3; ++r)
                if (!std::isfinite(float((*a)[c][r]))) return "overflows 32-bit float (it or its inverse)";
    return {};
}

void build_instances(const SceneDescription& d, uint32_t first_id, SceneInstances& out) {
    if (d.instances.empty()) return;
    out.meshes.resize(d.prototypes.size());
    for (std::size_t p = 0; p < d.prototypes.size(); ++p) {
        const MeshPrototype& proto = d.prototypes[p];
        InstancedMesh& mesh = out.meshes[p];
        const bool smooth = std::any_of(proto.parts.begin(), proto.parts.end(),
                                        [](const TriangleMesh& m) { return !m.normals.empty() && !m.triangles.empty(); });
        for (const TriangleMesh& part : proto.parts) {
            if (!part.normals.empty() && part.normals.size() != part.vertices.size())
                throw std::invalid_argument("build_scene: mesh \"" + proto.name + "\" has a part with " +
                                            std::to_string(part.normals.size()) + " normals for " +
                                            std::to_string(part.vertices.size()) + " vertices");
            if (d.materials[part.material].is_emissive())
                throw std::invalid_argument("build_scene: mesh \"" + proto.name +
                                            "\" emits light; the light table holds the scene's own triangles only");
            for (const auto& tri : part.triangles) {
                mesh.triangles.push_back(part.vertices[tri[0]], part.vertices[tri[1]], part.vertices[tri[2]], part.material);
                if (!smooth) continue;
                if (part.normals.empty()) mesh.shading_normals.push_flat();
                else mesh.shading_normals.push(part.normals[tri[0]], part.normals[tri[1]], part.normals[tri[2]]);
            }
        }
    }
    uint64_t next = first_id;
    out.first_id = first_id;
    out.instances.reserve(d.instances.size());
    for (std::size_t k = 0; k < d.instances.size(); ++k) {
        const InstanceDescription& in = d.instances[k];
        if (in.prototype >= d.prototypes.size())
            throw std::invalid_argument("build_scene: instance " + std::to_string(k) + " of mesh " +
                                        std::to_string(in.prototype) + ", which does not exist");
        const std::string problem = instance_transform_problem(in.transform);
        if (!problem.empty()) throw std::invalid_argument("build_scene: instance " + std::to_string(k) + ": its transform " + problem);
        if (out.meshes[in.prototype].triangles.size() == 0) continue;  // nothing to hit
        Instance placed;
        placed.to_world = AffineTransform::of(in.transform);
        placed.to_object = AffineTransform::of(glm::inverse(in.transform));
        placed.mesh = in.prototype;
        placed.first_id = uint32_t(next);
        next += out.meshes[in.prototype].triangles.size();
        if (next > kMaxPrimitiveIds)
            throw std::invalid_argument("build_scene: the instances place more than " + std::to_string(kMaxPrimitiveIds) +
                                        " triangles, more than a hit's 32-bit id can name");
        out.instances.push_back(placed);
    }
    out.triangle_count = next - first_id;
}

}  // namespace wt
