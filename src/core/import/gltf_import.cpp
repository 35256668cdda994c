// glTF 2.0 (.gltf with its .bin files, or .glb), parsed by tinygltf (see README.md,
// Dependencies). Every mesh primitive of mode TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN
// reachable from the scene's nodes becomes one piece placed by its node's world transform;
// points and lines are skipped with a note; KHR_lights_punctual lights are placed the same way
// (gltf_lights.h). The accessors are read and bounds-checked by
// gltf_accessor.h, since a buffer too short for them would otherwise be read past its end.

#include <cmath>
#include <cstring>
#include <unordered_map>
#include <unordered_set>

#include <tiny_gltf.h>

#include "core/geometry/mikktspace_tangents.h"
#include "core/import/gltf_accessor.h"
#include "core/import/gltf_lights.h"
#include "core/import/gltf_load.h"
#include "core/import/gltf_materials.h"
#include "core/import/gltf_nodes.h"
#include "core/import/mesh_file.h"
#include "core/import/primitive_triangles.h"

namespace wt {
namespace {

const char* mode_name(int mode) {
    static const char* const kNames[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP", "TRIANGLES", "TRIANGLE_STRIP", "TRIANGLE_FAN"};
    return mode >= 0 && mode <= 6 ? kNames[mode] : "not a mode";
}

class GltfReader {
public:
    GltfReader(const std::string& path, const tinygltf::Model& model, MeshFileUse use)
        : path_(path), model_(model), use_(use) {}

    ImportedMesh read() {
        const std::vector<int> roots = gltf_scene_roots(path_, model_);
        // A mesh that several nodes place is read once and placed by each (the scene stores it
        // once, as instances: core/instances/).
        std::vector<uint32_t> users(model_.meshes.size(), 0);
        uint64_t walked = 0;
        for (int root : roots) count_uses(root, 0, walked, users);
        shared_index_.assign(model_.meshes.size(), MeshPiece::kNotShared);
        for (std::size_t m = 0; m < users.size(); ++m)
            if (users[m] > 1) shared_index_[m] = mesh_.shared_count++;
        shared_read_.assign(mesh_.shared_count, false);
        // The materials first: which coordinates and tangents a primitive needs depends on them.
        GltfTextures textures(path_, model_, mesh_.textures, use_.file_materials);
        for (std::size_t i = 0; i < model_.materials.size(); ++i) {
            const tinygltf::Material& m = model_.materials[i];
            mesh_.materials.push_back(map_gltf_material(m, m.name.empty() ? "material " + std::to_string(i) : m.name, textures));
        }
        walk_gltf_nodes(path_, model_, roots, [&](int index, const tinygltf::Node& node, const glm::dmat4& world) {
            place_node(index, node, world);
        });
        // Points and lines alone are not "an empty mesh": say what the file has instead.
        if (mesh_.triangles.empty() && !first_skipped_.empty())
            fail("no triangles: its primitives are points or lines (" + first_skipped_ +
                 "), which have no surface to render");
        if (!all_have_normals_) mesh_.normals.clear();
        if (!all_have_normals_ && any_have_normals_)
            mesh_.notes.push_back("some primitives have no NORMAL: the file's normals are not used");
        if (!any_material_) mesh_.triangle_materials.clear();
        if (!any_have_uvs_) mesh_.uvs.clear();
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw MeshFileError(path_ + ": " + what); }

    // How many times the walk from the roots places each mesh. Only counts: the walk says what is
    // wrong with a bad hierarchy, and this walk stops where it would.
    void count_uses(int index, int depth, uint64_t& walked, std::vector<uint32_t>& users) const {
        if (index < 0 || std::size_t(index) >= model_.nodes.size() || depth > 256 || ++walked > (uint64_t(1) << 20)) return;
        const tinygltf::Node& node = model_.nodes[std::size_t(index)];
        if (node.mesh >= 0 && std::size_t(node.mesh) < users.size()) ++users[std::size_t(node.mesh)];
        for (int child : node.children) count_uses(child, depth + 1, walked, users);
    }

    // What one node places: its mesh (read once if shared) and its light.
    void place_node(int index, const tinygltf::Node& node, const glm::dmat4& world) {
        if (node.mesh >= 0) {
            if (std::size_t(node.mesh) >= model_.meshes.size())
                fail("node " + std::to_string(index) + ": mesh " + std::to_string(node.mesh) + " does not exist");
            const tinygltf::Mesh& mesh = model_.meshes[std::size_t(node.mesh)];
            const uint32_t shared = shared_index_[std::size_t(node.mesh)];
            if (shared != MeshPiece::kNotShared) mesh_.placements.push_back({shared, world});
            if (shared == MeshPiece::kNotShared || !shared_read_[shared]) {
                const std::size_t first_piece = mesh_.pieces.size();
                for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
                    read_primitive(mesh.primitives[p], "mesh " + std::to_string(node.mesh) + " primitive " + std::to_string(p),
                                   shared == MeshPiece::kNotShared ? world : glm::dmat4(1.0));
                if (shared != MeshPiece::kNotShared) {
                    shared_read_[shared] = true;
                    for (std::size_t p = first_piece; p < mesh_.pieces.size(); ++p) mesh_.pieces[p].shared = shared;
                }
            }
        }
        if (const int light = gltf_node_light(node); light != -1) read_gltf_light(path_, model_, light, world, mesh_);
    }

    std::string accessor_name(int index, const std::string& role, const std::string& where) const {
        return path_ + ": accessor " + std::to_string(index) + " (" + role + " of " + where + ")";
    }

    // FLOAT VEC3 elements, appended; positions and normals must be finite.
    void read_vec3s(const GltfAccessor& accessor, std::vector<glm::vec3>& out) const {
        const std::size_t first = out.size();
        out.resize(first + accessor.count());
        accessor.for_each([&](std::size_t i, const unsigned char* bytes) {
            glm::vec3& v = out[first + i];
            std::memcpy(&v, bytes, sizeof v);
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                throw MeshFileError(accessor.context() + ": element " + std::to_string(i) + " is not finite");
        });
    }

    // TEXCOORD_0 or TEXCOORD_1 (`attribute`; FLOAT, or normalised UNSIGNED_BYTE / UNSIGNED_SHORT),
    // appended to `out`; a primitive without it gets (0, 0). Returns whether the primitive has it.
    bool read_texture_coordinates(const tinygltf::Primitive& primitive, const std::string& where, std::size_t count,
                                  const std::string& attribute, std::vector<glm::vec2>& out) const {
        const std::size_t first = out.size();
        out.resize(first + count, glm::vec2(0.0f));
        const auto uv = primitive.attributes.find(attribute);
        if (uv == primitive.attributes.end()) return false;
        const GltfAccessor uvs(model_, uv->second, TINYGLTF_TYPE_VEC2,
                               {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                               accessor_name(uv->second, attribute, where));
        if (uvs.count() != count) fail(where + ": " + attribute + " and POSITION counts differ");
        const int type = uvs.component_type();
        uvs.for_each([&](std::size_t i, const unsigned char* bytes) {
            glm::vec2& t = out[first + i];
            if (type == TINYGLTF_COMPONENT_TYPE_FLOAT) {
                std::memcpy(&t, bytes, sizeof t);
            } else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
                t = glm::vec2(float(bytes[0]) / 255.0f, float(bytes[1]) / 255.0f);
            } else {
                uint16_t s[2];
                std::memcpy(s, bytes, sizeof s);
                t = glm::vec2(float(s[0]) / 65535.0f, float(s[1]) / 65535.0f);
            }
            if (!std::isfinite(t.x) || !std::isfinite(t.y))
                throw MeshFileError(uvs.context() + ": element " + std::to_string(i) + " is not finite");
        });
        return true;
    }

    // The primitive's material as mapped (the file's own), or null.
    const Material* material_of(const tinygltf::Primitive& primitive) const {
        if (primitive.material < 0 || std::size_t(primitive.material) >= mesh_.materials.size()) return nullptr;
        return &mesh_.materials[std::size_t(primitive.material)].material;
    }

    // The name of a texture of the primitive's material that reads TEXCOORD_1 ("FILE:
    // baseColorTexture of \"panel\""), or empty: only then is TEXCOORD_1 read.
    std::string second_set_texture(const tinygltf::Primitive& primitive) const {
        const Material* m = material_of(primitive);
        if (!m) return "";
        for (int32_t t : {m->color_texture, m->metallic_roughness_texture, m->normal_texture, m->alpha_texture, m->emission_texture})
            if (t >= 0 && mesh_.textures[std::size_t(t)].coordinate_set == 1) return mesh_.textures[std::size_t(t)].name;
        return "";
    }

    // The file's TANGENT (FLOAT VEC4, glTF 2.0 3.7.2.1), one per vertex from `first`; false,
    // with a note, where some element is unusable (not finite, zero, or w not a sign), so that
    // the primitive's tangents are made instead of any NaN reaching a shading normal.
    bool read_file_tangents(int index, const std::string& where, std::size_t first, std::size_t count) {
        const GltfAccessor tangents(model_, index, TINYGLTF_TYPE_VEC4, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                                    accessor_name(index, "TANGENT", where));
        if (tangents.count() != count) fail(where + ": TANGENT and POSITION counts differ");
        std::size_t unusable = 0;
        tangents.for_each([&](std::size_t i, const unsigned char* bytes) {
            glm::vec4 t;
            std::memcpy(&t, bytes, sizeof t);
            const float length = std::sqrt(t.x * t.x + t.y * t.y + t.z * t.z);
            if (!(length > 0.0f) || !std::isfinite(length) || !(t.w != 0.0f) || !std::isfinite(t.w)) ++unusable;
            else mesh_.tangents[first + i] = glm::vec4(glm::vec3(t) / length, t.w > 0.0f ? 1.0f : -1.0f);
        });
        if (unusable == 0) return true;
        mesh_.notes.push_back(tangents.context() + ": " + std::to_string(unusable) +
                              " TANGENT elements are not finite, zero or have w = 0: MikkTSpace tangents are used instead");
        return false;
    }

    // A normal-mapped primitive's tangents, its vertices `first` to `first + count` and its
    // triangles from `first_triangle`: the file's, else MikkTSpace's (the specification's
    // SHOULD). Those are per corner: a vertex whose corners got different ones (a seam between
    // mirrored halves) is split, its copies appended to the primitive.
    void add_tangents(const tinygltf::Primitive& primitive, const std::string& where, std::size_t first, std::size_t count,
                      std::size_t first_triangle) {
        mesh_.tangents.resize(mesh_.positions.size(), glm::vec4(0.0f));
        const auto tangent = primitive.attributes.find("TANGENT");
        if (tangent != primitive.attributes.end() && read_file_tangents(tangent->second, where, first, count)) return;
        const std::vector<std::array<uint32_t, 3>> triangles(mesh_.triangles.begin() + std::ptrdiff_t(first_triangle),
                                                             mesh_.triangles.end());
        // From the coordinates the normal texture reads (glTF 2.0, 3.7.2.1).
        const int32_t normal_texture = material_of(primitive)->normal_texture;
        const bool second = mesh_.textures[std::size_t(normal_texture)].coordinate_set == 1;
        const std::vector<glm::vec4> corners =
            mikktspace_tangents(mesh_.positions, mesh_.normals, second ? mesh_.second_uvs : mesh_.uvs, triangles);
        std::vector<bool> given(count, false);
        std::unordered_map<uint32_t, std::vector<uint32_t>> copies;
        for (std::size_t t = 0; t < triangles.size(); ++t)
            for (int c = 0; c < 3; ++c) {
                const uint32_t v = triangles[t][c];
                const glm::vec4& g = corners[3 * t + c];
                if (!given[v - first]) {
                    given[v - first] = true;
                    mesh_.tangents[v] = g;
                    continue;
                }
                if (mesh_.tangents[v] == g) continue;
                uint32_t copy = UINT32_MAX;
                for (uint32_t k : copies[v])
                    if (mesh_.tangents[k] == g) copy = k;
                if (copy == UINT32_MAX) {
                    copy = uint32_t(mesh_.positions.size());
                    mesh_.positions.push_back(mesh_.positions[v]);
                    if (!mesh_.normals.empty()) mesh_.normals.push_back(mesh_.normals[v]);
                    mesh_.uvs.push_back(mesh_.uvs[v]);
                    if (!mesh_.second_uvs.empty()) mesh_.second_uvs.push_back(mesh_.second_uvs[v]);
                    mesh_.tangents.push_back(g);
                    copies[v].push_back(copy);
                }
                mesh_.triangles[first_triangle + t][std::size_t(c)] = copy;
            }
    }

    void read_primitive(const tinygltf::Primitive& primitive, const std::string& where, const glm::dmat4& world) {
        const int mode = primitive.mode;
        if (mode < TINYGLTF_MODE_POINTS || mode > TINYGLTF_MODE_TRIANGLE_FAN)
            fail(where + ": mode " + std::to_string(mode) + " is not a glTF primitive mode (0 to 6)");
        if (mode < TINYGLTF_MODE_TRIANGLES) {
            const std::string what = where + ": mode " + std::to_string(mode) + ", " + mode_name(mode);
            if (first_skipped_.empty()) first_skipped_ = what;
            // Once per primitive, however many nodes place its mesh.
            if (skipped_.insert(where).second) mesh_.notes.push_back("skipped " + what + ": points and lines have no surface");
            return;
        }
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) fail(where + ": no POSITION attribute");
        const std::size_t first = mesh_.positions.size();
        const GltfAccessor positions(model_, position->second, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                                     accessor_name(position->second, "POSITION", where));
        if (first + positions.count() > UINT32_MAX)
            fail(where + ": the instances come to more than 2^32 - 1 vertices (the renderer's indices are 32-bit)");
        read_vec3s(positions, mesh_.positions);
        const auto normal = primitive.attributes.find("NORMAL");
        if (normal == primitive.attributes.end()) {
            all_have_normals_ = false;
        } else {
            any_have_normals_ = true;
            const GltfAccessor normals(model_, normal->second, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                                       accessor_name(normal->second, "NORMAL", where));
            if (normals.count() != positions.count()) fail(where + ": NORMAL and POSITION counts differ");
            read_vec3s(normals, mesh_.normals);
        }
        if (!all_have_normals_) std::vector<glm::vec3>().swap(mesh_.normals);
        const bool has_uvs = read_texture_coordinates(primitive, where, positions.count(), "TEXCOORD_0", mesh_.uvs);
        any_have_uvs_ |= has_uvs;
        // TEXCOORD_1 only where a texture reads it; missing there is an error, not a silently
        // wrong image (every texel read at (0, 0)).
        if (const std::string reader = second_set_texture(primitive); !reader.empty()) {
            mesh_.second_uvs.resize(first, glm::vec2(0.0f));
            if (!read_texture_coordinates(primitive, where, positions.count(), "TEXCOORD_1", mesh_.second_uvs))
                fail(where + ": no TEXCOORD_1, which " + reader.substr(path_.size() + 2) + " reads");
        }

        const std::size_t first_triangle = mesh_.triangles.size();
        PrimitiveTriangles triangles(PrimitiveMode(mode), mesh_.triangles);
        if (primitive.indices < 0) {  // non-indexed: the vertices in order
            check_vertex_count(positions.count(), mode, path_ + ": " + where + ": " + std::to_string(positions.count()) + " vertices");
            for (std::size_t v = 0; v < positions.count(); ++v) triangles.push(uint32_t(first + v));
        } else {
            read_indices(primitive.indices, where, mode, first, positions.count(), triangles);
        }
        if (first_triangle == mesh_.triangles.size()) fail(where + ": no triangles");
        const bool has_material = primitive.material >= 0;
        if (has_material && std::size_t(primitive.material) >= model_.materials.size())
            fail(where + ": material " + std::to_string(primitive.material) + " does not exist");
        any_material_ |= has_material;
        mesh_.triangle_materials.resize(mesh_.triangles.size(),
                                        has_material ? uint32_t(primitive.material) : ImportedMesh::kNoMaterial);
        // Only under a normal map (a scene without stores none). Without coordinates a normal
        // map reads one texel everywhere and has no frame to turn.
        const Material* material = use_.file_materials ? material_of(primitive) : nullptr;
        if (material && material->normal_texture >= 0 &&
            (mesh_.textures[std::size_t(material->normal_texture)].coordinate_set == 1 || has_uvs))
            add_tangents(primitive, where, first, positions.count(), first_triangle);
        if (!mesh_.tangents.empty()) mesh_.tangents.resize(mesh_.positions.size(), glm::vec4(0.0f));
        if (!mesh_.second_uvs.empty()) mesh_.second_uvs.resize(mesh_.positions.size(), glm::vec2(0.0f));
        if (mesh_.positions.size() > UINT32_MAX)
            fail(where + ": the instances come to more than 2^32 - 1 vertices (the renderer's indices are 32-bit)");
        mesh_.pieces.push_back({first, mesh_.positions.size() - first, world});
    }

    // TRIANGLES takes them three by three; a strip or fan needs 3 to make its first triangle.
    // `what` is the whole message so far: "FILE: accessor 3 (...): 7 indices".
    static void check_vertex_count(std::size_t count, int mode, const std::string& what) {
        if (mode == TINYGLTF_MODE_TRIANGLES && count % 3 != 0) throw MeshFileError(what + ", not a multiple of 3");
        if (mode != TINYGLTF_MODE_TRIANGLES && count < 3)
            throw MeshFileError(what + ", fewer than the 3 a " + (mode == TINYGLTF_MODE_TRIANGLE_STRIP ? "strip" : "fan") +
                                " needs");
    }

    void read_indices(int index, const std::string& where, int mode, std::size_t first, std::size_t vertex_count,
                      PrimitiveTriangles& triangles) const {
        const GltfAccessor indices(model_, index, TINYGLTF_TYPE_SCALAR,
                                   {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                   accessor_name(index, "indices", where));
        check_vertex_count(indices.count(), mode, indices.context() + ": " + std::to_string(indices.count()) + " indices");
        const int type = indices.component_type();
        indices.for_each([&](std::size_t i, const unsigned char* p) {
            uint32_t v = 0;
            if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) v = *p;
            else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) { uint16_t s; std::memcpy(&s, p, 2); v = s; }
            else std::memcpy(&v, p, 4);
            if (v >= vertex_count)
                throw MeshFileError(indices.context() + ": index " + std::to_string(i) + " is " + std::to_string(v) +
                                    ", out of range (" + std::to_string(vertex_count) + " vertices)");
            triangles.push(uint32_t(first + v));
        });
    }

    std::string path_;
    const tinygltf::Model& model_;
    ImportedMesh mesh_;
    std::vector<uint32_t> shared_index_;  // per glTF mesh: its shared index, or kNotShared
    std::vector<bool> shared_read_;
    bool all_have_normals_ = true;
    bool any_have_normals_ = false;
    bool any_have_uvs_ = false;
    MeshFileUse use_;
    bool any_material_ = false;
    std::unordered_set<std::string> skipped_;  // primitives of points or lines, noted once each
    std::string first_skipped_;
};

}  // namespace

ImportedMesh read_gltf_file(const std::string& path, MeshFileUse use) {
    const tinygltf::Model model = load_gltf_model(path);
    return GltfReader(path, model, use).read();
}

}  // namespace wt
