#include "core/scene/material_at_hit.h"

#include <array>
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
// the triangle's tangents t and b made orthogonal to it (Gram-Schmidt), as glTF 2.0 (3.9.3)
// defines normal maps. A flat texel (0.5, 0.5, 1) leaves the surface exactly as it was; so do a
// degenerate frame and a normal that does not come out finite.
void apply_normal_map(const glm::vec3& t, const glm::vec3& b_triangle, const glm::vec4& texel, const Material& m,
                      SurfacePoint& surface) {
    const float x = (2.0f * texel.x - 1.0f) * m.normal_scale, y = (2.0f * texel.y - 1.0f) * m.normal_scale;
    const float z = 2.0f * texel.z - 1.0f;
    if (x == 0.0f && y == 0.0f && z > 0.0f) return;
    const glm::vec3& n = surface.shading_normal;
    const glm::vec3 t_perpendicular = t - glm::dot(t, n) * n;
    const float t_length = glm::length(t_perpendicular);
    if (!(t_length > 0.0f)) return;
    const glm::vec3 tangent = t_perpendicular / t_length;
    // The bitangent's side from the triangle's own (a mirrored mapping flips it).
    const glm::vec3 b = glm::cross(n, tangent);
    const glm::vec3 bitangent = glm::dot(b, b_triangle) < 0.0f ? -b : b;
    const glm::vec3 mapped = x * tangent + y * bitangent + z * n;
    const float length = glm::length(mapped);
    if (!(length > 1e-6f) || !std::isfinite(length)) return;
    surface.shading_normal = mapped / length;
    surface.smooth = surface.shading_normal != surface.normal;
}

// Where a hit's texture coordinates are: the scene's own triangle's row, or the row of the
// instanced mesh's triangle with the placement that takes its tangents and density into world
// space. Spheres have none (`table` null).
struct CoordinateRow {
    const TextureCoordinateTable* table = nullptr;
    const TriangleSoA* triangles = nullptr;  // whose vertex indices find the row's coordinates
    std::size_t row = 0;
    const Instance* instance = nullptr;
    const InstancedMesh* mesh = nullptr;
};

CoordinateRow coordinate_row(const Scene& scene, const Hit& hit) {
    CoordinateRow c;
    if (hit.prim < scene.triangles.size()) {
        c.table = &scene.texture_coordinates, c.triangles = &scene.triangles, c.row = hit.prim;
    } else if (!scene.instances.empty() && hit.prim >= scene.instances.first_id) {
        c.instance = &scene.instances.instance_of(hit.prim);
        c.mesh = &scene.instances.meshes[c.instance->mesh];
        c.table = &c.mesh->texture_coordinates, c.triangles = &c.mesh->triangles, c.row = hit.prim - c.instance->first_id;
    }
    if (c.table && c.row >= c.table->size()) c.table = nullptr;
    return c;
}

// 0.5 log2(texture area / world area) of the hit's triangle in coordinate set `set`
// (TextureCoordinateTable::log2_density): an instanced triangle's is its object-space density
// less half the log2 of how much the placement scales its area.
float log2_density(const CoordinateRow& c, int set) {
    const float density = c.table->log2_density(c.row, set);
    if (!c.instance) return density;
    const glm::vec3 e1 = c.mesh->triangles.edge1(uint32_t(c.row)), e2 = c.mesh->triangles.edge2(uint32_t(c.row));
    const float object_area = glm::length(glm::cross(e1, e2));
    const float world_area = glm::length(glm::cross(c.instance->to_world.vector(e1), c.instance->to_world.vector(e2)));
    return object_area > 0.0f && world_area > 0.0f ? density - 0.5f * std::log2(world_area / object_area) : density;
}

// -1 where a placement mirrors (its linear part's determinant is negative), else 1.
float mirror_sign(const AffineTransform& a) {
    const glm::vec3 r0(a.m[0][0], a.m[0][1], a.m[0][2]), r1(a.m[1][0], a.m[1][1], a.m[1][2]), r2(a.m[2][0], a.m[2][1], a.m[2][2]);
    return glm::dot(r0, glm::cross(r1, r2)) < 0.0f ? -1.0f : 1.0f;
}

}  // namespace

void apply_textures(const Scene& scene, const Hit& hit, SurfacePoint& surface, const Ray& ray, bool from_camera,
                    Material& textured) {
    const CoordinateRow row = coordinate_row(scene, hit);
    const glm::vec2 uv = row.table ? row.table->at(*row.triangles, row.row, hit.u, hit.v) : sphere_coordinates(surface.normal);
    // Level of detail of a ray cone (Akenine-Moller et al. 2019, eq. 34): the triangle's texel
    // density plus log2 of the cone's width over the cosine of its incidence, plus the
    // texture's own term (added per texture below). Spheres and non-camera rays read level 0.
    // Each texture reads its own coordinate set (TextureImage::coordinate_set), with that set's density.
    float cone = -INFINITY;
    if (from_camera && row.table) {
        const float width = scene.cone_width0 + scene.cone_spread * hit.t;
        const float cosine = std::fabs(glm::dot(ray.direction, surface.normal));
        cone = std::log2(width / cosine);
    }
    const auto lookup = [&](int32_t texture) {
        const MipPyramid& t = scene.textures[std::size_t(texture)];
        const int set = row.table ? t.coordinate_set() : 0;
        const float lod = cone == -INFINITY ? -INFINITY : log2_density(row, set) + cone;
        return texture_lookup(t, t.transformed(set == 0 ? uv : row.table->at(*row.triangles, row.row, hit.u, hit.v, set)), lod + t.log2_texel_scale());
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
    if (textured.normal_texture >= 0 && row.table) {
        // An instanced triangle's tangents are in object space; tangents move with the placement.
        const TextureCoordinateTable::TangentFrame frame = row.table->tangent_frame(*row.triangles, row.row);
        glm::vec3 t = frame.tangent, b = frame.bitangent;
        if (const std::optional<std::array<glm::vec4, 3>> vertex = row.table->vertex_tangents(*row.triangles, row.row)) {
            // The file's or MikkTSpace's, interpolated like the normals (glTF 2.0, 3.7.2.1), the
            // bitangent cross(N, t) w. An instance places each vertex's and renormalises it, as
            // a flattened copy's are placed (a non-uniform scale changes their lengths unequally);
            // a mirroring placement turns the cross product the other way round, so w flips.
            glm::vec3 corner[3];
            for (int c = 0; c < 3; ++c) {
                corner[c] = glm::vec3((*vertex)[c]);
                if (row.instance) corner[c] = glm::normalize(row.instance->to_world.vector(corner[c]));
            }
            t = (1.0f - hit.u - hit.v) * corner[0] + hit.u * corner[1] + hit.v * corner[2];
            float w = (1.0f - hit.u - hit.v) * (*vertex)[0].w + hit.u * (*vertex)[1].w + hit.v * (*vertex)[2].w;
            if (row.instance) w *= mirror_sign(row.instance->to_world);
            b = (w < 0.0f ? -1.0f : 1.0f) * glm::cross(surface.shading_normal, t);
        } else if (row.instance) {
            t = row.instance->to_world.vector(t), b = row.instance->to_world.vector(b);
        }
        apply_normal_map(t, b, lookup(textured.normal_texture), textured, surface);
    }
    // glTF 2.0 (3.9.5): the emissive texture's RGB times emissiveFactor. Every ray but the
    // camera's reads level 0, as the light table's samples of the same point do
    // (core/lights/emission_textures.h), so a BSDF-sampled hit and a light sample weigh by MIS
    // the same radiance.
    if (textured.emission_texture >= 0) {
        const glm::vec4 c = lookup(textured.emission_texture);
        textured.emission *= glm::vec3(c.x, c.y, c.z);
    }
    if (textured.metallic_roughness_texture >= 0) {
        const glm::vec4 c = lookup(textured.metallic_roughness_texture);
        textured.roughness *= c.y;
        textured.metallic *= c.z;
    }
}

}  // namespace wt
