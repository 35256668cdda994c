#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/geometry/geometry_soa.h"
#include "core/scene_file/scene_schema.h"
#include "core/scene_file/scene_schema_instances.h"
#include "core/geometry/triangle_size.h"

// The shapes section: quads, inline meshes and spheres here, mesh files in import/.

namespace wt {
namespace {

constexpr const char* kShapeTypes = "quad, mesh, sphere, mesh_file, instance";

std::vector<glm::vec3> read_vertices(const Reader& in, const Json& j, const std::string& path) {
    in.expect_array(j, path);
    std::vector<glm::vec3> vertices;
    vertices.reserve(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) vertices.push_back(in.vec3(j[i], element_path(path, i)));
    return vertices;
}

TriangleMesh read_quad(const Reader& in, const Json& j, const std::string& path) {
    const std::string vpath = member_path(path, "vertices");
    const Json& vj = in.required(j, "vertices", path);
    if (!vj.is_array() || vj.size() != 4)
        in.fail(vpath, "a quad needs exactly 4 vertices [v0, v1, v2, v3], got " + describe(vj));
    TriangleMesh mesh;
    mesh.vertices = read_vertices(in, vj, vpath);
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};

    const glm::dvec3 v0(mesh.vertices[0]), v1(mesh.vertices[1]), v2(mesh.vertices[2]), v3(mesh.vertices[3]);
    for (std::size_t t = 0; t < 2; ++t) {
        const auto& tri = mesh.triangles[t];
        const glm::vec3 &qa = mesh.vertices[tri[0]], &qb = mesh.vertices[tri[1]], &qc = mesh.vertices[tri[2]];
        if (triangle_size(qa, qb, qc).degenerate() || is_sliver(qa, qb, qc))
            in.fail(vpath, "degenerate quad: its triangle " + std::to_string(t) + " (v" + std::to_string(tri[0]) +
                               ", v" + std::to_string(tri[1]) + ", v" + std::to_string(tri[2]) + ") has zero area");
    }
    const glm::dvec3 n0 = glm::cross(v1 - v0, v2 - v0);
    const glm::dvec3 n1 = glm::cross(v2 - v0, v3 - v0);
    const double size = std::max({glm::length(v1 - v0), glm::length(v2 - v0), glm::length(v3 - v0),
                                  glm::length(v2 - v1), glm::length(v3 - v1), glm::length(v3 - v2)});
    const double distance = std::fabs(glm::dot(v3 - v0, glm::normalize(n0)));
    if (distance > 1e-4 * size)
        in.fail(vpath, "non-planar quad: v3 is " + format_double(distance) + " from the plane of v0, v1, v2 (tolerance " +
                           format_double(1e-4 * size) + ")");
    // A planar quad whose vertices do not go around it makes a bow tie of two opposite-facing triangles.
    if (glm::dot(n0, n1) <= 0.0)
        in.fail(vpath, "quad vertices are not in order around its boundary (its two triangles face opposite ways)");
    // In double, v1 + v3 - v0 of floats is exact (barring exponents 29 binades apart), so this
    // asks whether the quad is a parallelogram as written, not up to rounding.
    mesh.parallelogram = v1 + v3 - v0 == v2;
    return mesh;
}

TriangleMesh read_mesh(const Reader& in, const Json& j, const std::string& path) {
    TriangleMesh mesh;
    const std::string vpath = member_path(path, "vertices");
    mesh.vertices = read_vertices(in, in.required(j, "vertices", path), vpath);
    if (mesh.vertices.size() < 3)
        in.fail(vpath, "a mesh needs at least 3 vertices, got " + std::to_string(mesh.vertices.size()));

    const std::string tpath = member_path(path, "triangles");
    const Json& tj = in.required(j, "triangles", path);
    in.expect_array(tj, tpath);
    if (tj.empty()) in.fail(tpath, "a mesh needs at least one triangle, got an empty array");
    const uint64_t last_vertex = mesh.vertices.size() - 1;
    mesh.triangles.reserve(tj.size());
    for (std::size_t t = 0; t < tj.size(); ++t) {
        if (!tj[t].is_array() || tj[t].size() != 3)
            in.fail(element_path(tpath, t), "expected an array of 3 vertex indices, got " + describe(tj[t]));
        std::array<uint32_t, 3> tri{};
        for (std::size_t k = 0; k < 3; ++k) {
            const std::string problem = integer_problem(tj[t][k], 0, last_vertex);
            if (!problem.empty()) in.fail(element_path(element_path(tpath, t), k), problem);
            tri[k] = uint32_t(tj[t][k].get<uint64_t>());
        }
        mesh.triangles.push_back(tri);
    }
    return mesh;
}

Sphere read_sphere(const Reader& in, const Json& j, const std::string& path) {
    Sphere s;
    s.center = in.vec3(in.required(j, "center", path), member_path(path, "center"));
    const Json& radius = in.required(j, "radius", path);
    s.radius = in.number(radius, member_path(path, "radius"));
    if (!(s.radius > 0.0f)) in.fail(member_path(path, "radius"), "must be positive, got " + describe(radius));
    return s;
}

}  // namespace

void read_shape(const Reader& in, const Json& j, const std::string& path, SceneDescription& scene,
                MaterialNames& names) {
    in.expect_object(j, path);
    if (!j.contains("type"))
        in.fail(member_path(path, "type"), std::string("required key is missing (one of ") + kShapeTypes + ")");
    const std::string type_path = member_path(path, "type");
    const std::string type = in.text(j.at("type"), type_path);
    if (type == "mesh_file") return read_mesh_file_shape(in, j, path, scene, names);
    const std::string context = " for a " + type;
    if (type == "quad") in.check_keys(j, path, {"type", "vertices", "material"}, context);
    else if (type == "mesh") in.check_keys(j, path, {"type", "vertices", "triangles", "material"}, context);
    else if (type == "sphere") in.check_keys(j, path, {"type", "center", "radius", "material"}, context);
    else in.fail(type_path, std::string("unknown shape type (allowed: ") + kShapeTypes + "), got " + describe(j.at("type")));

    const std::string material_path = member_path(path, "material");
    const uint32_t material = find_material(in, scene.materials, names, in.required(j, "material", path), material_path);
    const Material& m = scene.materials[material];

    if (type == "sphere") {
        // The light table holds triangles only.
        if (m.is_emissive())
            in.fail(material_path, "emissive spheres are not supported; use a mesh (material " + Json(m.name).dump() +
                                       " has emission " + format_vec3(m.emission) + ")");
        Sphere s = read_sphere(in, j, path);
        s.material = material;
        scene.spheres.push_back(s);
        return;
    }
    TriangleMesh mesh = type == "quad" ? read_quad(in, j, path) : read_mesh(in, j, path);
    mesh.material = material;
    // A textured quad shows its image upright when its corners run counter-clockwise from the
    // bottom left, seen from the front: v0 at the image's bottom-left corner (uv (0, 1)).
    if (type == "quad" && m.has_textures()) mesh.uvs = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
    if (m.is_emissive()) check_light_triangles(in, mesh, path);
    scene.meshes.push_back(std::move(mesh));
}

// The light table samples emissive triangles by area and skips empty ones, so a zero-area light
// would vanish without a word; it is nearly always a wrong vertex index or coordinate.
void check_light_triangles(const Reader& in, const TriangleMesh& mesh, const std::string& path) {
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const glm::vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
        const std::string vertices = " (vertices " + format_vec3(a) + ", " + format_vec3(b) + ", " + format_vec3(c) + ")";
        const float cross = float_cross_length(a, b, c);
        if (triangle_size(a, b, c).degenerate() || is_sliver(a, b, c) || cross == 0.0f)
            in.fail(element_path(member_path(path, "triangles"), t),
                    "degenerate light: emissive triangle " + std::to_string(t) + " has zero area" +
                        (cross == 0.0f ? " in 32-bit float" : "") + vertices);
        if (!std::isfinite(cross))
            in.fail(element_path(member_path(path, "triangles"), t),
                    "light too large: emissive triangle " + std::to_string(t) +
                        " has an area that overflows a 32-bit float" + vertices);
    }
}

void read_shapes(const Reader& in, const Json& j, const std::string& path, SceneDescription& scene, const Json* meshes) {
    in.expect_array(j, path);
    if (j.empty()) in.fail(path, "a scene needs at least one shape, got an empty array");
    MaterialNames names(scene.materials);
    NamedMeshes named(in, meshes, scene, names);
    for (std::size_t i = 0; i < j.size(); ++i) {
        const Json& shape = j[i];
        const Json* type = shape.is_object() ? in.optional(shape, "type") : nullptr;
        if (type && type->is_string() && type->get<std::string>() == "instance")
            named.place(shape, element_path(path, i));
        else
            read_shape(in, shape, element_path(path, i), scene, names);
    }
}


}  // namespace wt
