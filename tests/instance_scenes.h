#pragma once
// A scene with instances and the same scene flattened (every instance's triangles placed in
// world space, as a mesh_file with that transform would be: in double, rounded once, the winding
// reversed under a mirroring transform), for comparing the two hit by hit and image by image.

#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "core/description/scene_description.h"
#include "core/import/place_mesh.h"

namespace wt::test {

// A bumpy closed sphere of about 2 * rings * segments triangles, radius ~1 about the origin, with
// smooth vertex normals when `normals`.
inline TriangleMesh bumpy_sphere(int rings, int segments, bool normals) {
    TriangleMesh m;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const double theta = M_PI * r / rings, phi = 2.0 * M_PI * s / segments;
            const double radius = 1.0 + 0.08 * std::sin(5.0 * phi) * std::sin(3.0 * theta);
            const glm::dvec3 dir(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
            m.vertices.push_back(glm::vec3(radius * dir));
            if (normals) m.normals.push_back(glm::vec3(dir));
        }
    const auto at = [&](int r, int s) { return uint32_t(r * segments + (s % segments)); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            if (r > 0) m.triangles.push_back({at(r, s), at(r + 1, s), at(r, s + 1)});
            if (r + 1 < rings) m.triangles.push_back({at(r, s + 1), at(r + 1, s), at(r + 1, s + 1)});
        }
    return m;
}

// Placements that exercise the transform: translation, rotation, non-uniform scale, a mirror
// (negative determinant), a shear, and a tiny copy far from the origin.
inline std::vector<glm::dmat4> test_placements() {
    std::vector<glm::dmat4> t;
    t.push_back(glm::translate(glm::dmat4(1.0), {4.0, -2.0, 0.0}));
    t.push_back(glm::rotate(glm::translate(glm::dmat4(1.0), {5.0, 2.0, 0.5}), 0.7, glm::normalize(glm::dvec3(1, 2, 3))));
    t.push_back(glm::scale(glm::translate(glm::dmat4(1.0), {7.0, 0.0, -1.0}), {1.7, 0.4, 1.1}));
    glm::dmat4 mirror = glm::scale(glm::translate(glm::dmat4(1.0), {7.0, -3.0, 1.5}), {-1.0, 1.0, 1.0});
    t.push_back(glm::rotate(mirror, 1.1, glm::dvec3(0, 0, 1)));
    glm::dmat4 shear(1.0);
    shear[1][0] = 0.6, shear[2][1] = -0.3, shear[3] = glm::dvec4(9.0, 2.5, -0.5, 1.0);
    t.push_back(shear);
    t.push_back(glm::scale(glm::translate(glm::dmat4(1.0), {6.0, 0.0, 2.5}), glm::dvec3(1e-2)));
    t.push_back(glm::scale(glm::translate(glm::dmat4(1.0), {3.0, 3.0, -2.0}), {-0.5, -0.8, -0.6}));  // det < 0, all axes
    return t;
}

// A floor and a wall of the scene's own, the light, and the bumpy sphere placed by `placements`.
inline SceneDescription instanced_scene(const std::vector<glm::dmat4>& placements, bool normals, int rings = 12) {
    SceneDescription d;
    d.camera.eye = {-1.0f, 0.0f, 1.0f};
    d.camera.look_at = {6.0f, 0.0f, 0.0f};
    d.settings.width = 24, d.settings.height = 24, d.settings.spp = 16;
    Material white;
    white.name = "white", white.albedo = glm::vec3(0.7f);
    Material orange;
    orange.name = "orange", orange.albedo = {0.8f, 0.5f, 0.2f};
    Material light;
    light.name = "light", light.emission = glm::vec3(10.0f);
    d.materials = {white, orange, light};
    TriangleMesh floor;
    floor.vertices = {{0, -6, -2}, {12, -6, -2}, {12, 6, -2}, {0, 6, -2}, {12, -6, 5}, {12, 6, 5}};
    floor.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
    TriangleMesh lamp;
    lamp.vertices = {{4, -1, 4.5f}, {7, -1, 4.5f}, {7, 1, 4.5f}, {4, 1, 4.5f}};
    lamp.triangles = {{0, 2, 1}, {0, 3, 2}};
    lamp.material = 2;
    d.meshes = {floor, lamp};
    MeshPrototype proto;
    proto.name = "bumpy";
    proto.parts.push_back(bumpy_sphere(rings, 2 * rings, normals));
    proto.parts.back().material = 1;
    d.prototypes.push_back(proto);
    for (const glm::dmat4& m : placements) d.instances.push_back({0, m});
    return d;
}

// Every instance's parts moved into the scene's own meshes, after the existing ones: the
// flattened scene's triangle ids are then the instanced scene's (it has no spheres).
inline SceneDescription flattened(const SceneDescription& d) {
    SceneDescription f = d;
    f.prototypes.clear();
    f.instances.clear();
    for (const InstanceDescription& k : d.instances) {
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(k.transform)));
        const bool mirrored = glm::determinant(glm::dmat3(k.transform)) < 0.0;
        for (const TriangleMesh& part : d.prototypes[k.prototype].parts) {
            TriangleMesh placed = part;
            for (glm::vec3& v : placed.vertices) v = glm::vec3(k.transform * glm::dvec4(glm::dvec3(v), 1.0));
            for (glm::vec3& n : placed.normals) n = glm::vec3(glm::normalize(normal_matrix * glm::dvec3(n)));
            for (glm::vec4& t : placed.tangents) t = placed_tangent(t, glm::dmat3(k.transform));
            if (mirrored)
                for (auto& tri : placed.triangles) std::swap(tri[1], tri[2]);
            f.meshes.push_back(placed);
        }
    }
    return f;
}

}  // namespace wt::test
