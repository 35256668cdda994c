#pragma once
// The mirror caustic of light_tracing_test.cpp and photon_caustic_test.cpp: a scene whose floor
// is lit only through a mirror, and the floor's irradiance in closed form, which shares no code
// with the renderer.

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "core/description/scene_description.h"

namespace wt::test {

inline TriangleMesh quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, uint32_t material) {
    TriangleMesh m;
    m.vertices = {a, b, c, d};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.material = material;
    m.parallelogram = true;
    return m;
}

// The direction of the camera's ray through film position (fx, fy), by a pinhole model written
// here from the scene's description (not the renderer's Camera); not normalised.
inline glm::dvec3 view_direction(const SceneDescription& d, double fx, double fy) {
    const glm::dvec3 eye(d.camera.eye), forward = glm::normalize(glm::dvec3(d.camera.look_at) - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(d.camera.up)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double half_height = std::tan(0.5 * double(d.camera.fov_degrees) * M_PI / 180.0);
    const double half_width = half_height * d.settings.width / d.settings.height;
    const double sx = 2.0 * fx / d.settings.width - 1.0, sy = 1.0 - 2.0 * fy / d.settings.height;
    return forward + sx * half_width * right + sy * half_height * up;
}

// The mirror caustic: a diffuse floor (z = 0, albedo rho), a mirror ceiling (z = 2,
// reflectance R) and between them a small square light at z = 1 that emits only upwards, so the
// floor is lit only through the mirror. With max_bounces 3 the one path that carries light to
// the camera is camera -> floor -> mirror -> light: a caustic, all of it light tracing's.
struct MirrorCaustic {
    static constexpr float rho = 0.5f, reflectance = 0.9f, le = 20.0f, half_side = 0.15f;
    SceneDescription scene(int spp, uint64_t seed, CausticPaths caustics) const {
        SceneDescription d;
        Material floor, mirror, light;
        floor.albedo = glm::vec3(rho);
        mirror.type = MaterialType::mirror;
        mirror.reflectance = glm::vec3(reflectance);
        light.emission = glm::vec3(le);  // albedo 0: its black back casts the only shadow
        d.materials = {floor, mirror, light};
        const float s = 6.0f, h = half_side;
        d.meshes.push_back(quad({-s, -s, 0}, {s, -s, 0}, {s, s, 0}, {-s, s, 0}, 0));  // normal +z
        d.meshes.push_back(quad({-s, -s, 2}, {-s, s, 2}, {s, s, 2}, {s, -s, 2}, 1));  // normal -z
        d.meshes.push_back(quad({-h, -h, 1}, {h, -h, 1}, {h, h, 1}, {-h, h, 1}, 2));  // emits +z
        d.camera.eye = {0.0f, -2.2f, 1.4f};
        d.camera.look_at = {0.0f, 0.6f, 0.0f};
        d.camera.up = {0, 0, 1};
        d.camera.fov_degrees = 40.0f;
        d.settings.width = 24;
        d.settings.height = 24;
        d.settings.spp = spp;
        d.settings.seed = seed;
        d.settings.max_bounces = 3;
        d.settings.estimator.caustics = caustics;
        return d;
    }

    // Irradiance at floor point x from the light's mirror image (z = 3, facing down), by
    // Lambert's formula for a polygon of uniform radiance (Arvo 1995, eq. 4): E = Le / 2 *
    // sum_i angle(u_i, u_i+1) * (n . unit(u_i x u_i+1)), u_i the directions to its corners.
    static double image_irradiance(const glm::dvec3& x) {
        const double h = half_side;
        const glm::dvec3 corners[4] = {{-h, -h, 3}, {h, -h, 3}, {h, h, 3}, {-h, h, 3}};
        double sum = 0.0;
        for (int i = 0; i < 4; ++i) {
            const glm::dvec3 a = glm::normalize(corners[i] - x), b = glm::normalize(corners[(i + 1) % 4] - x);
            const glm::dvec3 c = glm::cross(a, b);
            sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * c.z / glm::length(c);
        }
        return 0.5 * double(le) * std::fabs(sum);
    }
    // Whether some path from x to the light's image crosses the real light's square (z = 1): the
    // mirror point of image point v is x + 2/3 (v - x), and the path meets z = 1 at x + (v - x)/3.
    static bool may_be_shadowed(const glm::dvec3& x) {
        const double reach = (2.0 / 3.0) * std::max(std::fabs(x.x), std::fabs(x.y)) - double(half_side) / 3.0;
        return reach <= double(half_side) + 1e-3;
    }
};

// The same caustic seen only through a second mirror: a wall mirror at y = 3 (facing -y, the
// ceiling's reflectance), and a camera that looks at it, down, from y = -0.5, so each pixel's
// view goes camera -> wall -> floor -> ceiling -> light: a caustic seen through a mirror
// (camera -> specular -> diffuse -> specular -> light), which light tracing cannot connect to
// the camera. max_bounces 4 keeps that one path: no other path of at most three surfaces carries
// light to the camera (the light emits only upwards, and the wall keeps a ray's vertical
// direction).
struct WallMirrorCaustic {
    static constexpr double wall_y = 3.0;
    static SceneDescription scene(int spp, uint64_t seed, CausticPaths caustics) {
        SceneDescription d = MirrorCaustic().scene(spp, seed, caustics);
        const float s = 6.0f, y = float(wall_y);
        d.meshes.push_back(quad({-s, y, 0}, {s, y, 0}, {s, y, 2}, {-s, y, 2}, 1));  // normal -y
        d.camera.eye = {0.0f, -0.5f, 1.6f};
        d.camera.look_at = {0.0f, 3.0f, 0.6f};
        d.camera.fov_degrees = 14.0f;
        d.settings.max_bounces = 4;
        return d;
    }

    // The floor point the camera sees in the wall at film position (fx, fy) (view_direction), if
    // the view meets the wall (below the ceiling) and then the floor well inside it, away from
    // the light's shadow and missing the light's square.
    static std::optional<glm::dvec3> floor_point(const SceneDescription& d, double fx, double fy) {
        const glm::dvec3 eye(d.camera.eye), dir = view_direction(d, fx, fy);
        const double h = MirrorCaustic::half_side + 1e-3;
        const auto crosses_light = [&](const glm::dvec3& from, const glm::dvec3& along, double t_end) {
            const double t = (1.0 - from.z) / along.z;
            const glm::dvec3 p = from + t * along;
            return t > 0.0 && t < t_end && std::fabs(p.x) <= h && std::fabs(p.y) <= h;
        };
        if (!(dir.y > 0.0)) return std::nullopt;
        const double t_wall = (wall_y - eye.y) / dir.y;
        const glm::dvec3 w = eye + t_wall * dir;
        if (!(w.z > 1e-3 && w.z < 2.0 - 1e-3 && std::fabs(w.x) < 5.9) || crosses_light(eye, dir, t_wall))
            return std::nullopt;
        const glm::dvec3 reflected(dir.x, -dir.y, dir.z);
        if (!(reflected.z < 0.0)) return std::nullopt;
        const double t_floor = -w.z / reflected.z;
        if (crosses_light(w, reflected, t_floor)) return std::nullopt;
        const glm::dvec3 x = w + t_floor * reflected;
        if (MirrorCaustic::may_be_shadowed(x) || std::fabs(x.x) > 5 || std::fabs(x.y) > 5) return std::nullopt;
        return x;
    }

    // The radiance the camera receives from floor point x through the wall.
    static double radiance(const glm::dvec3& x) {
        return MirrorCaustic::reflectance * MirrorCaustic::rho / M_PI * MirrorCaustic::reflectance *
               MirrorCaustic::image_irradiance(x);
    }
    // The same blurred by a disk of radius r about x on the floor, to leading order: the mean of a
    // smooth function over a disk is f + r^2 / 8 (f_xx + f_yy) + O(r^4). Its second derivatives by
    // central differences.
    static double radiance_blur(const glm::dvec3& x, double r_squared) {
        const double e = 0.02;
        const glm::dvec3 dx(e, 0, 0), dy(0, e, 0);
        const double laplacian =
            (radiance(x + dx) + radiance(x - dx) + radiance(x + dy) + radiance(x - dy) - 4.0 * radiance(x)) / (e * e);
        return r_squared / 8.0 * laplacian;
    }
};

}  // namespace wt::test
