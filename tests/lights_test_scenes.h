#pragma once
// Scenes and maps for the tests of the "lights" list (lights_*_test.cpp).

#include <cmath>
#include <memory>
#include <vector>

#include "core/description/scene_description.h"

namespace wt::test {

// A w x h map of varied, partly zero radiance: a bright spot, a gradient, a black band.
inline std::shared_ptr<const EnvironmentMap> test_environment_map(int w = 16, int h = 8) {
    auto map = std::make_shared<EnvironmentMap>();
    map->width = w, map->height = h;
    map->rgb.resize(std::size_t(w) * std::size_t(h) * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = 3 * (std::size_t(y) * std::size_t(w) + std::size_t(x));
            const float base = y == h / 2 ? 0.0f : 0.2f + 0.1f * float(x % 5) + 0.05f * float(y);
            const float spot = (x == 3 && y == 1) ? 40.0f : 0.0f;
            map->rgb[i] = base + spot, map->rgb[i + 1] = 0.5f * base + spot, map->rgb[i + 2] = 0.25f * base + 0.5f * spot;
        }
    return map;
}

inline LightDescription environment_light(std::shared_ptr<const EnvironmentMap> map, float strength = 1.0f,
                                          float rotate_degrees = 0.0f) {
    LightDescription l;
    l.type = LightType::environment;
    l.map = std::move(map);
    l.file = "test map";
    l.strength = strength;
    l.rotate_degrees = rotate_degrees;
    return l;
}

inline LightDescription constant_environment(glm::vec3 radiance) {
    LightDescription l;
    l.type = LightType::environment;
    l.radiance = radiance;
    return l;
}

// A scene in the z = 0 plane seen from 2 above, size x size pixels at `spp`, under a constant
// environment of radiance 1 (the texture and alpha import tests' view).
inline void view_from_above(SceneDescription& d, int size, int spp) {
    d.lights = {constant_environment(glm::vec3(1.0f))};
    d.camera.eye = glm::vec3(0.0f, 0.0f, 2.0f);
    d.camera.look_at = glm::vec3(0.0f);
    d.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    d.camera.fov_degrees = 40.0f;
    d.settings.width = d.settings.height = size;
    d.settings.spp = spp;
}

inline LightDescription point_light(glm::vec3 position, glm::vec3 intensity) {
    LightDescription l;
    l.type = LightType::point;
    l.position = position;
    l.intensity = intensity;
    return l;
}

inline LightDescription spot_light(glm::vec3 position, glm::vec3 direction, glm::vec3 intensity, float cone_degrees,
                                   float blend) {
    LightDescription l = point_light(position, intensity);
    l.type = LightType::spot;
    l.direction = direction;
    l.cone_degrees = cone_degrees;
    l.blend = blend;
    return l;
}

inline LightDescription directional_light(glm::vec3 direction, glm::vec3 irradiance, float angle_degrees) {
    LightDescription l;
    l.type = LightType::directional;
    l.direction = direction;
    l.irradiance = irradiance;
    l.angle_degrees = angle_degrees;
    return l;
}

// A spot's smoothstep towards a direction at cos_angle from its axis, written from the README's
// definition (not PunctualLight's): full inside the cone of cone_degrees x (1 - blend), nothing
// outside cone_degrees.
inline double spot_falloff(double cos_angle, double cone_degrees, double blend) {
    const double pi = 3.14159265358979323846;
    const double outer = std::cos(0.5 * cone_degrees * pi / 180.0);
    const double inner = std::cos(0.5 * cone_degrees * (1.0 - blend) * pi / 180.0);
    if (cos_angle >= inner) return 1.0;
    if (cos_angle <= outer) return 0.0;
    const double t = (cos_angle - outer) / (inner - outer);
    return t * t * (3.0 - 2.0 * t);
}

// A square Lambertian plane of albedo rho at z = 0, side `side`, facing +z, seen straight down
// from `eye_height` with a narrow field of view.
inline SceneDescription lit_plane(float rho, float side, float eye_height, float fov_degrees, int spp) {
    SceneDescription d;
    d.camera.eye = {0.0f, 0.0f, eye_height};
    d.camera.look_at = {0.0f, 0.0f, 0.0f};
    d.camera.up = {0.0f, 1.0f, 0.0f};
    d.camera.fov_degrees = fov_degrees;
    d.settings.width = d.settings.height = 8;
    d.settings.spp = spp;
    Material m;
    m.name = "plane";
    m.albedo = glm::vec3(rho);
    d.materials = {m};
    const float s = 0.5f * side;
    TriangleMesh plane;
    plane.vertices = {{-s, -s, 0.0f}, {s, -s, 0.0f}, {s, s, 0.0f}, {-s, s, 0.0f}};
    plane.triangles = {{0, 1, 2}, {0, 2, 3}};
    plane.parallelogram = true;
    d.meshes = {plane};
    return d;
}

// A Lambertian sphere of albedo rho (radius 1 at the origin) filling the whole image.
inline SceneDescription sphere_filling_the_image(glm::vec3 rho, int spp) {
    SceneDescription d;
    d.camera.eye = {0.0f, -4.0f, 0.0f};
    d.camera.look_at = {0.0f, 0.0f, 0.0f};
    d.camera.up = {0.0f, 0.0f, 1.0f};
    d.camera.fov_degrees = 20.0f;  // the corners are 14.0 degrees off axis, the sphere's edge 14.5
    d.settings.width = d.settings.height = 12;
    d.settings.spp = spp;
    Material m;
    m.name = "grey";
    m.albedo = rho;
    d.materials = {m};
    d.spheres = {Sphere{glm::vec3(0.0f), 1.0f, 0}};
    return d;
}

}  // namespace wt::test
