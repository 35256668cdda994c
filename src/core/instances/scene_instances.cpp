#include "core/instances/scene_instances.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/description/vertex_attribute_counts.h"
#include "core/geometry/mesh_texture_coordinates.h"
#include "core/instances/build_instances.h"

namespace wt {

const Instance& SceneInstances::instance_of(uint32_t prim) const {
    const auto after = std::upper_bound(instances.begin(), instances.end(), prim,
                                        [](uint32_t p, const Instance& k) { return p < k.first_id; });
    return *(after - 1);
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
    // Coordinates only if some material will read them, as for the scene's own triangles.
    const bool textured = std::any_of(d.materials.begin(), d.materials.end(), [](const Material& m) { return m.has_textures(); });
    for (std::size_t p = 0; p < d.prototypes.size(); ++p) {
        const MeshPrototype& proto = d.prototypes[p];
        InstancedMesh& mesh = out.meshes[p];
        mesh.triangles.store_only_for(d.settings.accuracy.triangles);
        mesh.triangles.reserve_for(proto.parts);
        const bool smooth = std::any_of(proto.parts.begin(), proto.parts.end(),
                                        [](const TriangleMesh& m) { return !m.normals.empty() && !m.triangles.empty(); });
        for (const TriangleMesh& part : proto.parts) {
            check_vertex_attribute_counts(part, "mesh \"" + proto.name + "\" has a part with");
            if (d.materials[part.material].is_emissive())
                throw std::invalid_argument("build_scene: mesh \"" + proto.name +
                                            "\" emits light; the light table holds the scene's own triangles only");
            const uint32_t first = add_mesh_vertices(part.vertices, part.normals, smooth, mesh.triangles, mesh.shading_normals);
            if (textured) add_texture_vertices(mesh.texture_coordinates, part);
            for (const auto& tri : part.triangles) {
                mesh.triangles.push(first + tri[0], first + tri[1], first + tri[2], part.material);
                if (textured) push_texture_triangle(mesh.texture_coordinates, part, first, tri);
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
