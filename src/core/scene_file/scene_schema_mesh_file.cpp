#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/geometry/geometry_soa.h"
#include "core/import/mesh_file.h"
#include "core/import/place_mesh.h"
#include "core/import/shared_meshes.h"
#include "core/instances/build_instances.h"
#include "core/scene_file/scene_schema.h"
#include "core/geometry/triangle_size.h"

// "type": "mesh_file": a shape whose triangles come from an OBJ, PLY or glTF file.

namespace wt {
namespace {

constexpr const char* kFromFile = "from_file";

NormalsMode read_normals_mode(const Reader& in, const Json& j, const std::string& path) {
    const std::string mode = in.text(j, path);
    if (mode == "file") return NormalsMode::file;
    if (mode == "smooth") return NormalsMode::smooth;
    if (mode == "flat") return NormalsMode::flat;
    in.fail(path, "must be one of \"file\", \"smooth\", \"flat\", got " + describe(j));
}

// The file's materials, named "FILE/NAME" with FILE as the scene wrote it, appended to the
// scene's unless a material of that name exists: then that one is used, so the same file used
// twice shares its materials and a scene can override one of them by defining its name.
// Returns our index for each of the file's materials, and for "none" (the last entry).
std::vector<uint32_t> add_file_materials(const ImportedMesh& mesh, const std::string& file, SceneDescription& scene,
                                         MaterialNames& names, std::vector<std::string>& unmapped) {
    const auto index_of = [&](const Material& m) {
        if (const std::optional<uint32_t> existing = names.find(m.name)) return *existing;
        scene.materials.push_back(m);
        return uint32_t(scene.materials.size() - 1);
    };
    // The file's textures follow the scene's; its materials' indices move with them.
    const int32_t first_texture = int32_t(scene.textures.size());
    scene.textures.insert(scene.textures.end(), mesh.textures.begin(), mesh.textures.end());
    std::vector<uint32_t> ours;
    for (std::size_t i = 0; i < mesh.materials.size(); ++i) {
        Material m = mesh.materials[i].material;
        if (m.color_texture >= 0) m.color_texture += first_texture;
        const std::string file_name = m.name.empty() ? "material " + std::to_string(i) : m.name;
        m.name = file + "/" + file_name;
        ours.push_back(index_of(m));
        if (!mesh.materials[i].unmapped.empty()) unmapped.push_back(file_name + ": " + join(mesh.materials[i].unmapped));
    }
    Material fallback;
    fallback.name = file + "/default";
    fallback.albedo = glm::vec3(0.8f);
    const bool any_without = mesh.triangle_materials.empty() ||
                             std::count(mesh.triangle_materials.begin(), mesh.triangle_materials.end(),
                                        ImportedMesh::kNoMaterial) > 0;
    ours.push_back(any_without ? index_of(fallback) : UINT32_MAX);
    return ours;
}

// One TriangleMesh per material, in the order the materials first appear, each with only the
// vertices its triangles use, in the file's order; texture coordinates only where the material
// has a texture.
void split_by_material(const ImportedMesh& mesh, const std::vector<uint32_t>& ours, const std::vector<Material>& materials,
                       std::vector<TriangleMesh>& out) {
    const uint32_t none = uint32_t(ours.size() - 1);
    const auto group_of = [&](std::size_t t) {
        const uint32_t m = mesh.triangle_materials.empty() ? ImportedMesh::kNoMaterial : mesh.triangle_materials[t];
        return m == ImportedMesh::kNoMaterial ? none : m;
    };
    std::vector<std::vector<uint32_t>> triangles_of(ours.size());
    std::vector<uint32_t> order;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const uint32_t g = group_of(t);
        if (triangles_of[g].empty()) order.push_back(g);
        triangles_of[g].push_back(uint32_t(t));
    }
    std::vector<uint32_t> remap(mesh.positions.size(), UINT32_MAX);
    for (const uint32_t g : order) {
        std::vector<uint32_t> used;
        for (uint32_t t : triangles_of[g])
            for (uint32_t v : mesh.triangles[t]) {
                if (remap[v] != UINT32_MAX) continue;
                remap[v] = 0;  // seen; numbered below, in the file's order
                used.push_back(v);
            }
        std::sort(used.begin(), used.end());
        TriangleMesh part;
        part.material = ours[g];
        const bool uvs = !mesh.uvs.empty() && materials[part.material].has_textures();
        const bool tangents = uvs && !mesh.tangents.empty() && materials[part.material].normal_texture >= 0;
        const bool second_uvs = uvs && !mesh.second_uvs.empty();
        for (uint32_t v : used) {
            remap[v] = uint32_t(part.vertices.size());
            part.vertices.push_back(mesh.positions[v]);
            if (!mesh.normals.empty()) part.normals.push_back(mesh.normals[v]);
            if (uvs) part.uvs.push_back(mesh.uvs[v]);
            if (tangents) part.tangents.push_back(mesh.tangents[v]);
            if (second_uvs) part.second_uvs.push_back(mesh.second_uvs[v]);
        }
        for (uint32_t t : triangles_of[g]) {
            const auto& tri = mesh.triangles[t];
            part.triangles.push_back({remap[tri[0]], remap[tri[1]], remap[tri[2]]});
        }
        for (uint32_t v : used) remap[v] = UINT32_MAX;
        out.push_back(std::move(part));
    }
}

// A part placed by m as place_mesh would place it: positions in double rounded once, normals by
// the inverse transpose, the winding reversed under a mirroring m.
TriangleMesh placed_copy(const TriangleMesh& part, const glm::dmat4& m) {
    TriangleMesh out = part;
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(m)));
    for (glm::vec3& v : out.vertices) v = glm::vec3(m * glm::dvec4(glm::dvec3(v), 1.0));
    for (glm::vec3& n : out.normals) n = glm::vec3(glm::normalize(normal_matrix * glm::dvec3(n)));
    for (glm::vec4& t : out.tangents) t = placed_tangent(t, glm::dmat3(m));
    if (glm::determinant(glm::dmat3(m)) < 0.0)
        for (auto& tri : out.triangles) std::swap(tri[1], tri[2]);
    return out;
}

}  // namespace

void read_mesh_file_shape(const Reader& in, const Json& j, const std::string& path, SceneDescription& scene,
                          MaterialNames& names) {
    in.check_keys(j, path, {"type", "file", "material", "transform", "normals"}, " for a mesh_file");
    const std::string file_path = member_path(path, "file");
    const std::string file = in.text(in.required(j, "file", path), file_path);
    if (file.empty()) in.fail(file_path, "must not be empty");
    const std::string resolved = in.resolve(file);

    const std::string material_path = member_path(path, "material");
    const Json& material = in.required(j, "material", path);
    const bool from_file = material.is_string() && material.get<std::string>() == kFromFile;
    const uint32_t scene_material = from_file ? 0 : find_material(in, scene.materials, names, material, material_path);
    glm::dmat4 transform(1.0);
    if (const Json* t = in.optional(j, "transform")) transform = read_transform(in, *t, member_path(path, "transform"));
    NormalsMode normals = NormalsMode::file;
    if (const Json* n = in.optional(j, "normals")) normals = read_normals_mode(in, *n, member_path(path, "normals"));

    ImportedMesh mesh;
    try {
        mesh = read_mesh_file(resolved, MeshFileUse{from_file, !from_file && scene.materials[scene_material].has_textures()});
    } catch (const MeshFileError& e) {
        in.fail(file_path, e.what());
    }
    // A file that places a mesh more than once (glTF nodes sharing a mesh) has it stored once and
    // placed by instances; its materials are then taken from the whole file before the split.
    const bool has_shared = mesh.shared_count > 0;
    std::vector<std::string> unmapped;
    std::vector<uint32_t> ours;
    if (from_file && has_shared) ours = add_file_materials(mesh, file, scene, names, unmapped);
    std::vector<ImportedMesh> shared = take_shared_meshes(mesh);
    const std::vector<SharedMeshPlacement> placements = std::move(mesh.placements);
    const std::string note = in.source() + ": " + file_path + ": " + resolved + ": ";
    for (const std::string& n : mesh.notes) scene.notes.push_back(note + n);
    // One TriangleMesh per material (from_file), else the whole mesh in the scene's material.
    const auto add_parts = [&](ImportedMesh& m, std::vector<TriangleMesh>& out) {
        if (from_file) return split_by_material(m, ours, scene.materials, out);
        TriangleMesh whole;
        whole.vertices = std::move(m.positions);
        whole.triangles = std::move(m.triangles);
        whole.normals = std::move(m.normals);
        if (scene.materials[scene_material].has_textures()) whole.uvs = std::move(m.uvs);
        whole.material = scene_material;
        out.push_back(std::move(whole));
    };
    const auto place = [&](ImportedMesh& m, const glm::dmat4& t, const std::string& what) {
        const std::size_t in_file = m.triangles.size();
        const std::size_t dropped = place_mesh(m, t, normals);
        if (dropped > 0)
            scene.notes.push_back(note + "dropped " + std::to_string(dropped) + " degenerate (zero-area) triangles of " +
                                  std::to_string(in_file) + what);
    };

    // The file's lights (glTF's KHR_lights_punctual), through the shape's transform as its triangles.
    for (LightDescription l : mesh.lights) {
        l.position = glm::vec3(transform * glm::dvec4(glm::dvec3(l.position), 1.0));
        const glm::dvec3 axis(transform * glm::dvec4(glm::dvec3(l.direction), 0.0));
        const double length = glm::length(axis);
        if (!(length > 0.0 && std::isfinite(length)) || !std::isfinite(l.position.x + l.position.y + l.position.z))
            in.fail(file_path, resolved + ": the transform leaves a light of the file no position or direction");
        l.direction = glm::vec3(axis / length);
        scene.lights.push_back(l);
    }

    const std::size_t first_new = scene.meshes.size();
    place(mesh, transform, "");
    if (mesh.triangles.empty() && shared.empty())
        in.fail(file_path, resolved + ": every triangle is degenerate (zero area)" +
                               (j.contains("transform") ? " after the transform" : ""));
    if (from_file && !has_shared) ours = add_file_materials(mesh, file, scene, names, unmapped);
    if (!unmapped.empty()) scene.notes.push_back(note + "not mapped from its materials: " + join(unmapped));
    if (!mesh.triangles.empty()) add_parts(mesh, scene.meshes);
    for (uint32_t s = 0; s < shared.size(); ++s) {
        place(shared[s], glm::dmat4(1.0), " of shared mesh " + std::to_string(s));
        if (shared[s].triangles.empty()) continue;
        MeshPrototype proto;
        proto.name = file + "#" + std::to_string(s);
        add_parts(shared[s], proto.parts);
        const bool emits = std::any_of(proto.parts.begin(), proto.parts.end(),
                                       [&](const TriangleMesh& p) { return scene.materials[p.material].is_emissive(); });
        std::vector<glm::dmat4> transforms;
        for (const SharedMeshPlacement& p : placements) {
            if (p.shared != s) continue;
            const glm::dmat4 m = transform * p.transform;
            const std::string problem = instance_transform_problem(m);
            if (problem.empty()) transforms.push_back(m);
            else scene.notes.push_back(note + "skipped a placement of shared mesh " + std::to_string(s) + ": its transform " + problem);
        }
        // The light table lists the scene's own triangles: an emitting shared mesh is placed
        // flattened, once per placement, as before instancing.
        if (emits) {
            for (const glm::dmat4& m : transforms)
                for (const TriangleMesh& part : proto.parts) scene.meshes.push_back(placed_copy(part, m));
            continue;
        }
        uint64_t triangles = 0;
        for (const TriangleMesh& part : proto.parts) triangles += part.triangles.size();
        if (double(triangles) * double(transforms.size()) > double(kMaxPrimitiveIds))
            in.fail(file_path, resolved + ": shared mesh " + std::to_string(s) + " placed " + std::to_string(transforms.size()) +
                                   " times makes more than the " + std::to_string(kMaxPrimitiveIds) +
                                   " triangles a hit's 32-bit id can name");
        scene.prototypes.push_back(std::move(proto));
        for (const glm::dmat4& m : transforms) scene.instances.push_back({uint32_t(scene.prototypes.size() - 1), m});
    }
    // The light table cannot sample a triangle stored collapsed (see is_sliver).
    for (std::size_t i = first_new; i < scene.meshes.size(); ++i) {
        const TriangleMesh& part = scene.meshes[i];
        if (!scene.materials[part.material].is_emissive()) continue;
        for (const auto& tri : part.triangles) {
            const glm::vec3 &a = part.vertices[tri[0]], &b = part.vertices[tri[1]], &c = part.vertices[tri[2]];
            const float cross = float_cross_length(a, b, c);
            if (is_sliver(a, b, c) || cross == 0.0f)
                in.fail(file_path, resolved + ": an emissive triangle (material " + Json(scene.materials[part.material].name).dump() +
                                       ") is too thin to be sampled as a light");
            if (!std::isfinite(cross))
                in.fail(file_path, resolved + ": an emissive triangle (material " + Json(scene.materials[part.material].name).dump() +
                                       ") has an area that overflows a 32-bit float");
        }
    }
}

}  // namespace wt
