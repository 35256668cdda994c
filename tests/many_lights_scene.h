#pragma once
// A room lit by many small emissive triangles of different power, for the tests of light
// selection by power and by the light tree (light_selection_*_test.cpp).

#include <cstdint>

#include "core/description/scene_description.h"

namespace wt::test {

// A 4 x 4 x 2 room whose ceiling holds (0.05 below it) an n x n grid of small triangles facing down, their
// emission spread over two decades (four materials, assigned by a hash of the cell), and a few
// tilted ones facing the walls; a rough metal block on the floor, diffuse walls and floor.
inline SceneDescription many_lights_room(int n, LightSampling light_sampling, LightSelection selection) {
    SceneDescription d;
    d.camera.eye = {-1.8f, -1.8f, 1.4f};
    d.camera.look_at = {0.5f, 0.5f, 0.3f};
    d.camera.up = {0.0f, 0.0f, 1.0f};
    d.camera.fov_degrees = 70.0f;
    d.settings.width = d.settings.height = 16;
    d.settings.spp = 64;
    d.settings.max_bounces = 4;
    d.settings.estimator.light_sampling = light_sampling;
    d.settings.estimator.light_selection = selection;
    const auto material = [&](const char* name, glm::vec3 albedo, glm::vec3 emission) {
        Material m;
        m.name = name;
        m.albedo = albedo;
        m.emission = emission;
        d.materials.push_back(m);
        return uint32_t(d.materials.size() - 1);
    };
    const uint32_t wall = material("wall", glm::vec3(0.6f), glm::vec3(0.0f));
    const uint32_t floor = material("floor", glm::vec3(0.7f, 0.6f, 0.5f), glm::vec3(0.0f));
    const uint32_t lamps[4] = {material("lamp0", glm::vec3(0.0f), glm::vec3(0.4f)),
                               material("lamp1", glm::vec3(0.0f), glm::vec3(2.0f, 1.5f, 1.0f)),
                               material("lamp2", glm::vec3(0.0f), glm::vec3(6.0f, 8.0f, 10.0f)),
                               material("lamp3", glm::vec3(0.0f), glm::vec3(40.0f))};
    Material metal;
    metal.name = "rough metal";
    metal.type = MaterialType::rough_conductor;
    metal.roughness = 0.3f;
    metal.f0 = glm::vec3(0.9f, 0.8f, 0.6f);
    d.materials.push_back(metal);
    const uint32_t rough = uint32_t(d.materials.size() - 1);

    const auto quad = [&](uint32_t m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 e) {
        TriangleMesh q;
        q.vertices = std::vector<glm::vec3>{a, b, c, e};
        q.triangles = {{0, 1, 2}, {0, 2, 3}};
        q.material = m;
        d.meshes.push_back(q);
    };
    // Wound so the normals face into the room.
    quad(floor, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0});
    quad(wall, {-2, -2, 2}, {-2, 2, 2}, {2, 2, 2}, {2, -2, 2});
    quad(wall, {-2, -2, 0}, {-2, 2, 0}, {-2, 2, 2}, {-2, -2, 2});
    quad(wall, {2, -2, 0}, {2, -2, 2}, {2, 2, 2}, {2, 2, 0});
    quad(wall, {-2, -2, 0}, {-2, -2, 2}, {2, -2, 2}, {2, -2, 0});
    quad(wall, {-2, 2, 0}, {2, 2, 0}, {2, 2, 2}, {-2, 2, 2});
    // The rough metal block's top and two faces towards the camera.
    quad(rough, {0.2f, 0.2f, 0.6f}, {1.2f, 0.2f, 0.6f}, {1.2f, 1.2f, 0.6f}, {0.2f, 1.2f, 0.6f});
    quad(rough, {0.2f, 0.2f, 0.0f}, {1.2f, 0.2f, 0.0f}, {1.2f, 0.2f, 0.6f}, {0.2f, 0.2f, 0.6f});
    quad(rough, {0.2f, 0.2f, 0.0f}, {0.2f, 0.2f, 0.6f}, {0.2f, 1.2f, 0.6f}, {0.2f, 1.2f, 0.0f});

    // The grid keeps 0.6 from the walls: a wall point right beside an emitter sees it at a
    // distance near zero, where selection by area has a tail too heavy for a per-pixel z-test.
    const float cell = 2.8f / float(n), size = 0.35f * cell;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t h = uint32_t(i * 7919 + j * 104729) * 2654435761u;
            TriangleMesh t;
            const glm::vec3 c(-1.4f + (float(i) + 0.5f) * cell, -1.4f + (float(j) + 0.5f) * cell, 1.95f);
            // One in eight tilted by 60 degrees about x, so the cones of the tree differ.
            const float tilt = (h >> 7) % 8 == 0 ? 0.866f : 0.0f;
            t.vertices = std::vector<glm::vec3>{c, c + glm::vec3(0.0f, size * (1.0f - 0.5f * tilt), -size * tilt), c + glm::vec3(size, 0.0f, 0.0f)};
            t.triangles = {{0, 1, 2}};
            t.material = lamps[(h >> 13) % 4];
            d.meshes.push_back(t);
        }
    return d;
}

}  // namespace wt::test
