#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>

#include "core/geometry_soa.h"
#include "core/import/mesh_file.h"
#include "core/import/place_mesh.h"
#include "core/scene_file/scene_schema.h"
#include "core/scene_file/triangle_size.h"

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
        for (uint32_t v : used) {
            remap[v] = uint32_t(part.vertices.size());
            part.vertices.push_back(mesh.positions[v]);
            if (!mesh.normals.empty()) part.normals.push_back(mesh.normals[v]);
            if (uvs) part.uvs.push_back(mesh.uvs[v]);
        }
        for (uint32_t t : triangles_of[g]) {
            const auto& tri = mesh.triangles[t];
            part.triangles.push_back({remap[tri[0]], remap[tri[1]], remap[tri[2]]});
        }
        for (uint32_t v : used) remap[v] = UINT32_MAX;
        out.push_back(std::move(part));
    }
}

}  // namespace

void read_mesh_file_shape(const Reader& in, const Json& j, const std::string& path, SceneDescription& scene,
                          MaterialNames& names) {
    in.check_keys(j, path, {"type", "file", "material", "transform", "normals"}, " for a mesh_file");
    const std::string file_path = member_path(path, "file");
    const std::string file = in.text(in.required(j, "file", path), file_path);
    if (file.empty()) in.fail(file_path, "must not be empty");
    const std::filesystem::path relative(file);
    const std::string resolved =
        relative.is_absolute() ? file : (std::filesystem::path(in.source()).parent_path() / relative).string();

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
    const std::size_t triangles_in_file = mesh.triangles.size();
    const std::size_t dropped = place_mesh(mesh, transform, normals);
    const std::string note = in.source() + ": " + file_path + ": " + resolved + ": ";
    for (const std::string& n : mesh.notes) scene.notes.push_back(note + n);
    if (dropped > 0)
        scene.notes.push_back(note + "dropped " + std::to_string(dropped) + " degenerate (zero-area) triangles of " +
                              std::to_string(triangles_in_file));
    if (mesh.triangles.empty())
        in.fail(file_path, resolved + ": every triangle is degenerate (zero area)" +
                               (j.contains("transform") ? " after the transform" : ""));

    const std::size_t first_new = scene.meshes.size();
    if (from_file) {
        std::vector<std::string> unmapped;
        const std::vector<uint32_t> ours = add_file_materials(mesh, file, scene, names, unmapped);
        if (!unmapped.empty()) scene.notes.push_back(note + "not mapped from its materials: " + join(unmapped));
        split_by_material(mesh, ours, scene.materials, scene.meshes);
    } else {
        TriangleMesh whole;
        whole.vertices = std::move(mesh.positions);
        whole.triangles = std::move(mesh.triangles);
        whole.normals = std::move(mesh.normals);
        if (scene.materials[scene_material].has_textures()) whole.uvs = std::move(mesh.uvs);
        whole.material = scene_material;
        scene.meshes.push_back(std::move(whole));
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
