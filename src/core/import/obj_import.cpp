// Wavefront OBJ and its MTL materials, parsed by tinyobjloader (see README.md, Dependencies).
// tinyobjloader names lines only for the few errors it raises itself; what it accepts is then
// checked here, where a vertex can be named by its number (the n-th "v" line) and a face by its
// number in the file, but not by its line.

#include <cmath>
#include <filesystem>
#include <unordered_map>

#include <tiny_obj_loader.h>

#include "core/import/mesh_file.h"
#include "core/import/obj_materials.h"
#include "core/import/polygon_fan.h"

namespace wt {
namespace {

std::string first_line(const std::string& text) {
    std::string s = text.substr(0, text.find('\n'));
    while (!s.empty() && (s.back() == '\r' || s.back() == ' ')) s.pop_back();
    return s;
}

// One output vertex per distinct (position, normal) pair a face corner names. A position keeps
// its index and the file's order when its corners agree on the normal (the common case), and
// is copied to the end once per other normal it is given.
class CornerVertices {
public:
    CornerVertices(ImportedMesh& mesh, const tinyobj::attrib_t& attrib, bool with_normals)
        : mesh_(mesh), attrib_(attrib), with_normals_(with_normals),
          normal_of_(with_normals ? mesh.positions.size() : 0, -1) {
        if (with_normals) mesh_.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    }

    uint32_t vertex(int position, int normal) {
        if (!with_normals_) return uint32_t(position);
        int& assigned = normal_of_[std::size_t(position)];
        if (assigned < 0 || assigned == normal) {
            assigned = normal;
            mesh_.normals[std::size_t(position)] = normal_vector(normal);
            return uint32_t(position);
        }
        const uint64_t key = (uint64_t(uint32_t(position)) << 32) | uint32_t(normal);
        const auto [it, inserted] = split_.try_emplace(key, uint32_t(mesh_.positions.size()));
        if (inserted) {
            mesh_.positions.push_back(mesh_.positions[std::size_t(position)]);
            mesh_.normals.push_back(normal_vector(normal));
        }
        return it->second;
    }

private:
    glm::vec3 normal_vector(int normal) const {
        const float* n = &attrib_.normals[3 * std::size_t(normal)];
        return {n[0], n[1], n[2]};
    }

    ImportedMesh& mesh_;
    const tinyobj::attrib_t& attrib_;
    bool with_normals_;
    std::vector<int> normal_of_;
    std::unordered_map<uint64_t, uint32_t> split_;
};

}  // namespace

ImportedMesh read_obj_file(const std::string& path) {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    const std::string base_dir = std::filesystem::path(path).parent_path().string();
    const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, path.c_str(),
                                     (base_dir.empty() ? std::string("./") : base_dir + "/").c_str(),
                                     /*triangulate=*/false, /*default_vcols_fallback=*/false);
    if (!ok) throw MeshFileError(path + ": " + first_line(err.empty() ? warn : err));
    // tinyobjloader drops such a face with this warning, and without its line.
    if (warn.find("Degenerated face found") != std::string::npos)
        throw MeshFileError(path + ": a face has fewer than 3 vertices (tinyobjloader does not say on which line)");

    ImportedMesh mesh;
    const std::size_t vertex_count = attrib.vertices.size() / 3;
    const std::size_t normal_count = attrib.normals.size() / 3;
    mesh.positions.resize(vertex_count);
    for (std::size_t v = 0; v < vertex_count; ++v) {
        const glm::vec3 p(attrib.vertices[3 * v], attrib.vertices[3 * v + 1], attrib.vertices[3 * v + 2]);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw MeshFileError(path + ": vertex " + std::to_string(v + 1) + " (the " + std::to_string(v + 1) +
                                "th \"v\" line) is not finite");
        mesh.positions[v] = p;
    }
    std::vector<float>().swap(attrib.vertices);
    for (float n : attrib.normals)
        if (!std::isfinite(n)) throw MeshFileError(path + ": a vertex normal (\"vn\") is not finite");

    // File normals only if every face corner names one: a mesh half smooth and half flat would
    // have no consistent shading normal to give its flat half.
    bool every_corner_has_normal = normal_count > 0;
    for (const tinyobj::shape_t& shape : shapes)
        for (const tinyobj::index_t& corner : shape.mesh.indices) every_corner_has_normal &= corner.normal_index >= 0;
    if (normal_count > 0 && !every_corner_has_normal)
        mesh.notes.push_back("some faces name no vertex normal (\"vn\"): the file's normals are not used");

    CornerVertices corners(mesh, attrib, every_corner_has_normal);
    bool any_material = false;
    std::size_t face_number = 0;  // 1-based, over the whole file, for messages
    std::vector<uint32_t> polygon;
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t corner = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            ++face_number;
            const std::size_t n = shape.mesh.num_face_vertices[f];
            const std::string face = "face " + std::to_string(face_number) +
                                     (shape.name.empty() ? "" : " (in group \"" + shape.name + "\")");
            polygon.clear();
            for (std::size_t k = 0; k < n; ++k, ++corner) {
                const tinyobj::index_t& index = shape.mesh.indices[corner];
                // tinyobjloader resolves negative (relative) indices; one reaching before the
                // first vertex comes out negative.
                if (index.vertex_index < 0 || std::size_t(index.vertex_index) >= vertex_count)
                    throw MeshFileError(path + ": " + face + ": vertex index out of range (resolves to " +
                                        std::to_string(index.vertex_index + 1) + "; the file has " +
                                        std::to_string(vertex_count) + " vertices)");
                if (every_corner_has_normal && std::size_t(index.normal_index) >= normal_count)
                    throw MeshFileError(path + ": " + face + ": normal index out of range (resolves to " +
                                        std::to_string(index.normal_index + 1) + "; the file has " +
                                        std::to_string(normal_count) + " normals)");
                polygon.push_back(corners.vertex(index.vertex_index, index.normal_index));
            }
            append_polygon_fan(polygon, mesh.triangles);
            const int material = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
            any_material |= material >= 0;
            mesh.triangle_materials.resize(mesh.triangles.size(),
                                           material >= 0 ? uint32_t(material) : ImportedMesh::kNoMaterial);
        }
    }
    if (!any_material) mesh.triangle_materials.clear();
    for (const tinyobj::material_t& m : materials) mesh.materials.push_back(map_obj_material(m));
    if (!warn.empty() && materials.empty() && warn.find("Material") != std::string::npos)
        mesh.notes.push_back(first_line(warn));
    mesh.pieces.push_back({0, mesh.positions.size(), glm::dmat4(1.0)});
    return mesh;
}

}  // namespace wt
