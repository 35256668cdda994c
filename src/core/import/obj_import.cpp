// Wavefront OBJ and its MTL materials, parsed by tinyobjloader (see README.md, Dependencies)
// through its streaming callbacks: each "v" and "f" line reaches us as it is read, so nothing
// but our own mesh is built, and indices are resolved and checked here. tinyobjloader does not
// pass line numbers to callbacks, so a vertex is named by its number (the n-th "v" line) and a
// face by its number in the file (the n-th "f" line).

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <unordered_map>

#include <tiny_obj_loader.h>

#include "core/import/mesh_file.h"
#include "core/regular_file.h"
#include "core/import/obj_materials.h"
#include "core/import/polygon_fan.h"

namespace wt {
namespace {

// What the callbacks build. A callback cannot stop the parse, so the first problem is kept and
// thrown once tinyobjloader returns.
struct ObjBuilder {
    ImportedMesh mesh;
    std::vector<glm::vec3> file_normals;
    std::vector<int32_t> corner_normals;  // per triangle corner, an index into file_normals or -1
    std::vector<tinyobj::material_t> materials;
    uint32_t material = ImportedMesh::kNoMaterial;
    bool any_material = false;
    std::string group;
    uint64_t faces = 0;
    // Positive indices may name vertices defined further down; those are checked at the end.
    std::vector<std::pair<uint64_t, int64_t>> forward_references;  // (face, 1-based index)
    std::string problem;

    std::string face_name() const {
        return "face " + std::to_string(faces) + (group.empty() ? "" : " (in group \"" + group + "\")");
    }

    void fail(const std::string& what) {
        if (problem.empty()) problem = what;
    }

    // OBJ counts from 1; a negative index counts back from the last element defined so far.
    // Returns the 0-based index, or -1 after recording the problem.
    int64_t resolve(int raw, std::size_t defined, const char* what) {
        if (raw == 0) {
            fail(face_name() + ": " + what + " index 0 (OBJ counts from 1)");
            return -1;
        }
        const int64_t index = raw > 0 ? int64_t(raw) - 1 : int64_t(defined) + raw;
        if (index < 0)
            fail(face_name() + ": " + what + " index " + std::to_string(raw) + " reaches before the first (" +
                 std::to_string(defined) + " defined so far)");
        return index;
    }

    void face(const tinyobj::index_t* corners, int count) {
        ++faces;
        if (!problem.empty()) return;
        if (count < 3) return fail(face_name() + ": a face needs at least 3 vertices, got " + std::to_string(count));
        polygon_.clear();
        polygon_normals_.clear();
        for (int k = 0; k < count; ++k) {
            const int64_t v = resolve(corners[k].vertex_index, mesh.positions.size(), "vertex");
            if (v < 0) return;
            if (uint64_t(v) >= mesh.positions.size()) forward_references.push_back({faces, v + 1});
            polygon_.push_back(uint32_t(v));
            int64_t n = -1;
            if (corners[k].normal_index != 0) {
                n = resolve(corners[k].normal_index, file_normals.size(), "normal");
                if (n < 0) return;
                if (uint64_t(n) >= file_normals.size())
                    return fail(face_name() + ": normal index " + std::to_string(corners[k].normal_index) +
                                " out of range (" + std::to_string(file_normals.size()) + " normals defined so far)");
            }
            polygon_normals_.push_back(int32_t(n));
        }
        for (std::size_t k = 1; k + 1 < polygon_normals_.size(); ++k)
            corner_normals.insert(corner_normals.end(), {polygon_normals_[0], polygon_normals_[k], polygon_normals_[k + 1]});
        append_polygon_fan(polygon_, mesh.triangles);
        mesh.triangle_materials.resize(mesh.triangles.size(), material);
    }

private:
    std::vector<uint32_t> polygon_;
    std::vector<int32_t> polygon_normals_;
};

tinyobj::callback_t obj_callbacks() {
    tinyobj::callback_t cb;
    cb.vertex_cb = [](void* user, float x, float y, float z, float) {
        ObjBuilder& b = *static_cast<ObjBuilder*>(user);
        b.mesh.positions.push_back({x, y, z});
        if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
            b.fail("vertex " + std::to_string(b.mesh.positions.size()) + " (the " + std::to_string(b.mesh.positions.size()) +
                   "th \"v\" line) is not finite");
    };
    cb.normal_cb = [](void* user, float x, float y, float z) {
        ObjBuilder& b = *static_cast<ObjBuilder*>(user);
        b.file_normals.push_back({x, y, z});
        if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
            b.fail("normal " + std::to_string(b.file_normals.size()) + " (\"vn\") is not finite");
    };
    cb.index_cb = [](void* user, tinyobj::index_t* corners, int count) { static_cast<ObjBuilder*>(user)->face(corners, count); };
    cb.usemtl_cb = [](void* user, const char* name, int id) {
        ObjBuilder& b = *static_cast<ObjBuilder*>(user);
        b.material = id >= 0 ? uint32_t(id) : ImportedMesh::kNoMaterial;
        b.any_material |= id >= 0;
        if (id < 0) b.mesh.notes.push_back("usemtl " + std::string(name) + ": no such material in the .mtl files");
    };
    cb.mtllib_cb = [](void* user, const tinyobj::material_t* materials, int count) {
        static_cast<ObjBuilder*>(user)->materials.assign(materials, materials + count);
    };
    cb.group_cb = [](void* user, const char** names, int count) {
        static_cast<ObjBuilder*>(user)->group = count > 0 ? names[0] : "";
    };
    cb.object_cb = [](void* user, const char* name) { static_cast<ObjBuilder*>(user)->group = name; };
    return cb;
}

// One output vertex per distinct (position, normal) pair a face corner names. A position keeps
// its index and the file's order when its corners agree on the normal (the common case), and
// is copied to the end once per other normal it is given.
void split_vertices_by_normal(ObjBuilder& b) {
    ImportedMesh& mesh = b.mesh;
    std::vector<int32_t> normal_of(mesh.positions.size(), -1);
    std::unordered_map<uint64_t, uint32_t> copies;
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (std::size_t k = 0; k < 3; ++k) {
            uint32_t& v = mesh.triangles[t][k];
            const int32_t n = b.corner_normals[3 * t + k];
            if (normal_of[v] < 0 || normal_of[v] == n) {
                normal_of[v] = n;
                mesh.normals[v] = b.file_normals[std::size_t(n)];
                continue;
            }
            const auto [it, inserted] = copies.try_emplace((uint64_t(v) << 32) | uint32_t(n), uint32_t(mesh.positions.size()));
            if (inserted) {
                mesh.positions.push_back(mesh.positions[v]);
                mesh.normals.push_back(b.file_normals[std::size_t(n)]);
            }
            v = it->second;
        }
    }
}

// tinyobjloader's MTL reader, for regular files within the mesh-file limit only: `mtllib
// /dev/zero` would otherwise read one endless line.
class RegularMaterialFileReader : public tinyobj::MaterialReader {
public:
    explicit RegularMaterialFileReader(std::string dir) : dir_(dir), reader_(std::move(dir)) {}
    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials, std::map<std::string, int>* ids,
                    std::string* warn, std::string* err) override {
        try {
            open_regular_file(dir_ + name, kMaxMeshFileBytes);
        } catch (const InputFileError& e) {
            if (warn) *warn += "Failed to load material file(s). " + std::string(e.what()) + "\n";
            return false;
        }
        return reader_(name, materials, ids, warn, err);
    }

private:
    std::string dir_;
    tinyobj::MaterialFileReader reader_;
};

}  // namespace

ImportedMesh read_obj_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw MeshFileError(path + ": cannot open");
    const std::string base_dir = std::filesystem::path(path).parent_path().string();
    RegularMaterialFileReader mtl_reader(base_dir.empty() ? std::string("./") : base_dir + "/");
    ObjBuilder b;
    std::string warn, err;
    const bool ok = tinyobj::LoadObjWithCallback(in, obj_callbacks(), &b, &mtl_reader, &warn, &err);
    if (!ok || !err.empty()) throw MeshFileError(path + ": " + first_line(err.empty() ? warn : err));
    if (in.bad()) throw MeshFileError(path + ": read error");
    if (!b.problem.empty()) throw MeshFileError(path + ": " + b.problem);
    for (const auto& [face, index] : b.forward_references)
        if (uint64_t(index) > b.mesh.positions.size())
            throw MeshFileError(path + ": face " + std::to_string(face) + ": vertex index " + std::to_string(index) +
                                " out of range (the file has " + std::to_string(b.mesh.positions.size()) + " vertices)");
    if (warn.find("Failed to load material file") != std::string::npos) b.mesh.notes.push_back(first_line(warn));

    // File normals only if every face corner names one: a mesh half smooth and half flat would
    // have no consistent shading normal to give its flat half.
    const bool every_corner_has_normal =
        !b.file_normals.empty() && std::find(b.corner_normals.begin(), b.corner_normals.end(), -1) == b.corner_normals.end();
    if (!b.file_normals.empty() && !every_corner_has_normal)
        b.mesh.notes.push_back("some faces name no vertex normal (\"vn\"): the file's normals are not used");
    if (every_corner_has_normal) split_vertices_by_normal(b);
    std::vector<int32_t>().swap(b.corner_normals);

    if (!b.any_material) b.mesh.triangle_materials.clear();
    for (const tinyobj::material_t& m : b.materials) b.mesh.materials.push_back(map_obj_material(m));
    b.mesh.pieces.push_back({0, b.mesh.positions.size(), glm::dmat4(1.0)});
    return std::move(b.mesh);
}

}  // namespace wt
