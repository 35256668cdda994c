#pragma once
// Scenes the tests build in code or load from scenes/, at test-sized resolutions.

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "core/scene/scene.h"
#include "core/description/scene_description.h"
#include "core/scene_file/scene_loader.h"

namespace wt::test {

inline std::string scene_path(const std::string& name) { return std::string(WT_SCENES_DIR) + "/" + name; }

inline SceneDescription hexroom(int width, int height, int spp, uint64_t seed = 0) {
    SceneDescription d = load_scene_file(scene_path("hexroom.json"));
    d.settings.width = width;
    d.settings.height = height;
    d.settings.spp = spp;
    d.settings.seed = seed;
    return d;
}

// A closed cube [-1,1]^3 seen from inside; every face diffuse with albedo rho and emitting Le.
// Radiance everywhere is Le / (1 - rho): the white furnace.
inline SceneDescription furnace_cube(float rho, float le, MaterialType type = MaterialType::lambertian, float sigma = 0.0f) {
    SceneDescription d;
    Material m;
    m.name = "furnace";
    m.type = type;
    m.albedo = glm::vec3(rho);
    m.sigma = sigma;
    m.emission = glm::vec3(le);
    d.materials.push_back(m);
    // Each face as a quad wound so cross(v1 - v0, v2 - v0) points into the cube.
    const glm::vec3 c[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const int faces[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 5, 6, 2}};
    TriangleMesh mesh;
    for (const glm::vec3& v : c) mesh.vertices.push_back(v);
    for (const auto& f : faces) {
        mesh.triangles.push_back({uint32_t(f[0]), uint32_t(f[1]), uint32_t(f[2])});
        mesh.triangles.push_back({uint32_t(f[0]), uint32_t(f[2]), uint32_t(f[3])});
    }
    d.meshes.push_back(mesh);
    // The view stays 0.6 away from the cube's edges. Next-event estimation at a point near a
    // concave edge has unbounded variance (G ~ 1/d^2 towards the adjacent face), which would
    // make per-pixel confidence intervals meaningless for the pixels that see it.
    d.camera.eye = glm::vec3(0.0f, 0.0f, 0.0f);
    d.camera.look_at = glm::vec3(1.0f, 0.0f, 0.0f);
    d.camera.up = glm::vec3(0, 0, 1);
    d.camera.fov_degrees = 40.0f;
    d.settings.width = 16;
    d.settings.height = 16;
    d.settings.spp = 256;
    d.settings.shadow_rays = 2;
    return d;
}

// Icosahedron subdivided `levels` times, vertices pushed onto the sphere of radius r around
// center; wound counter-clockwise seen from outside.
inline TriangleMesh icosphere(int levels, float r = 1.0f, glm::vec3 center = glm::vec3(0.0f)) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    TriangleMesh m;
    for (glm::vec3 v : {glm::vec3(-1, t, 0), glm::vec3(1, t, 0), glm::vec3(-1, -t, 0), glm::vec3(1, -t, 0),
                        glm::vec3(0, -1, t), glm::vec3(0, 1, t), glm::vec3(0, -1, -t), glm::vec3(0, 1, -t),
                        glm::vec3(t, 0, -1), glm::vec3(t, 0, 1), glm::vec3(-t, 0, -1), glm::vec3(-t, 0, 1)})
        m.vertices.push_back(glm::normalize(v));
    m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint;
        auto mid = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = midpoint.find(key);
            if (it != midpoint.end()) return it->second;
            m.vertices.push_back(glm::normalize(m.vertices[a] + m.vertices[b]));
            return midpoint[key] = uint32_t(m.vertices.size() - 1);
        };
        std::vector<std::array<uint32_t, 3>> next;
        for (const auto& tri : m.triangles) {
            const uint32_t a = mid(tri[0], tri[1]), b = mid(tri[1], tri[2]), c = mid(tri[2], tri[0]);
            next.push_back({tri[0], a, c}), next.push_back({tri[1], b, a}), next.push_back({tri[2], c, b}), next.push_back({a, b, c});
        }
        m.triangles = next;
    }
    for (glm::vec3& v : m.vertices) v = center + r * v;
    return m;
}

}  // namespace wt::test
