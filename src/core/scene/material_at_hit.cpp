#include "core/scene/material_at_hit.h"

#include <cmath>

#include "core/sampling/sampling.h"
#include "core/textures/texture_lookup.h"

namespace wt {

namespace {

// A sphere's coordinates: longitude about +y for u, the polar angle from +y for v (v = 0 at
// the top), as an equirectangular map wraps it.
glm::vec2 sphere_coordinates(const glm::vec3& n) {
    const float u = 0.5f + std::atan2(n.x, -n.z) * (0.5f * kInvPi);
    const float v = std::acos(n.y < -1.0f ? -1.0f : (n.y > 1.0f ? 1.0f : n.y)) * kInvPi;
    return {u, v};
}

// The tangent-space normal (2 c - 1, x and y scaled) about the frame of the shading normal N and
// the triangle's tangents made orthogonal to it (Gram-Schmidt), as glTF 2.0 (3.9.3) defines
// normal maps. A flat texel (0.5, 0.5, 1) leaves the surface exactly as it was; so do a
// degenerate frame and a normal that does not come out finite.
void apply_normal_map(const Scene& scene, const Hit& hit, const glm::vec4& texel, const Material& m, SurfacePoint& surface) {
    const float x = (2.0f * texel.x - 1.0f) * m.normal_scale, y = (2.0f * texel.y - 1.0f) * m.normal_scale;
    const float z = 2.0f * texel.z - 1.0f;
    if (x == 0.0f && y == 0.0f && z > 0.0f) return;
    const glm::vec3& n = surface.shading_normal;
    const glm::vec3 t = scene.texture_coordinates.tangent(hit.prim);
    const glm::vec3 t_perpendicular = t - glm::dot(t, n) * n;
    const float t_length = glm::length(t_perpendicular);
    if (!(t_length > 0.0f)) return;
    const glm::vec3 tangent = t_perpendicular / t_length;
    // The bitangent's side from the triangle's own (a mirrored mapping flips it).
    const glm::vec3 b = glm::cross(n, tangent);
    const glm::vec3 bitangent = glm::dot(b, scene.texture_coordinates.bitangent(hit.prim)) < 0.0f ? -b : b;
    const glm::vec3 mapped = x * tangent + y * bitangent + z * n;
    const float length = glm::length(mapped);
    if (!(length > 1e-6f) || !std::isfinite(length)) return;
    surface.shading_normal = mapped / length;
    surface.smooth = surface.shading_normal != surface.normal;
}

}  // namespace

void apply_textures(const Scene& scene, const Hit& hit, SurfacePoint& surface, const Ray& ray, bool from_camera,
                    Material& textured) {
    const bool triangle = hit.prim < scene.triangles.size();
    const glm::vec2 uv = triangle ? scene.texture_coordinates.at(hit.prim, hit.u, hit.v) : sphere_coordinates(surface.normal);
    // Level of detail of a ray cone (Akenine-Moller et al. 2019, eq. 34): the triangle's texel
    // density plus log2 of the cone's width over the cosine of its incidence, plus the
    // texture's own term (added per texture below). Spheres and non-camera rays read level 0.
    float lod = -INFINITY;
    if (from_camera && triangle) {
        const float width = scene.cone_width0 + scene.cone_spread * hit.t;
        const float cosine = std::fabs(glm::dot(ray.direction, surface.normal));
        lod = scene.texture_coordinates.log2_density(hit.prim) + std::log2(width / cosine);
    }
    const auto lookup = [&](int32_t texture) {
        const MipPyramid& t = scene.textures[std::size_t(texture)];
        return texture_lookup(t, t.transformed(uv), lod + t.log2_texel_scale());
    };
    if (textured.color_texture >= 0) {
        const glm::vec4 c = lookup(textured.color_texture);
        const glm::vec3 rgb(c.x, c.y, c.z);
        // The colour each type has: a principled material's base colour, a metal's F0 (glTF's
        // metallic 1 loads as one, its base colour as F0), else the diffuse albedo.
        if (textured.type == MaterialType::principled) textured.base_color *= rgb;
        else if (textured.type == MaterialType::conductor || textured.type == MaterialType::rough_conductor) textured.f0 *= rgb;
        else textured.albedo *= rgb;
    }
    if (textured.normal_texture >= 0 && triangle) apply_normal_map(scene, hit, lookup(textured.normal_texture), textured, surface);
    if (textured.metallic_roughness_texture >= 0) {
        const glm::vec4 c = lookup(textured.metallic_roughness_texture);
        textured.roughness *= c.y;
        textured.metallic *= c.z;
    }
}

}  // namespace wt
