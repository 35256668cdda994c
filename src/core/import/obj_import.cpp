// Wavefront OBJ (the format as Paul Bourke documents it), read line by line through a fixed
// buffer by our own reader, so that every message names the line, and a number that is not
// one (`v abc`, `v nan`, an index past 2^63) is an error in the file's own words rather than
// the 0 or the wrapped int tinyobjloader would hand over. MTL files are tinyobjloader's
// (obj_materials.h). Only what becomes triangles is read: v, vn, vt, f, mtllib and usemtl; o,
// g, s, lines, points and free-form geometry are skipped.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <unordered_map>
#include <unordered_set>

#include "core/import/file_bytes.h"
#include "core/import/mesh_file.h"
#include "core/import/obj_materials.h"
#include "core/import/polygon_fan.h"
#include "core/import/text_words.h"

namespace wt {
namespace {

class ObjReader {
public:
    ObjReader(const std::string& path, MeshFileUse use) : path_(path), in_(path), use_(use) {
        base_dir_ = std::filesystem::path(path).parent_path();
    }

    ImportedMesh read() {
        std::string buffer;
        while (in_.read_line(buffer)) {
            // A lone "\r" ends a line too (old Mac files); "\r\n" is gone already.
            std::string_view rest(buffer);
            if (line_ == 0) skip_byte_order_mark(rest);
            for (std::size_t cr; (cr = rest.find('\r')) != std::string_view::npos; rest.remove_prefix(cr + 1)) {
                ++line_;
                statement(rest.substr(0, cr));
            }
            ++line_;
            statement(rest);
        }
        finish();
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const { fail_at(line_, what); }

    [[noreturn]] void fail_at(uint64_t line, const std::string& what) const {
        throw MeshFileError(path_ + ":" + std::to_string(line) + ": " + what);
    }

    void note(const std::string& what) { mesh_.notes.push_back("line " + std::to_string(line_) + ": " + what); }

    // A UTF-8 mark would make the first keyword unknown, and the first "v" lost unnoticed.
    void skip_byte_order_mark(std::string_view& first_line) const {
        if (first_line.substr(0, 3) == "\xEF\xBB\xBF") first_line.remove_prefix(3);
        if (first_line.substr(0, 2) == "\xFE\xFF" || first_line.substr(0, 2) == "\xFF\xFE")
            fail_at(1, "the file is UTF-16 text (it starts with a byte order mark); OBJ is read as ASCII or UTF-8");
    }

    void statement(std::string_view line) {
        TextWords words(line);
        const std::string_view keyword = words.next();
        if (keyword == "v") mesh_.positions.push_back(coordinates(words, "vertex"));
        else if (keyword == "vn") file_normals_.push_back(coordinates(words, "normal"));
        else if (keyword == "f") face(words);
        else if (keyword == "vt") texture_coordinate(words);
        else if (keyword == "usemtl") use_material(std::string(words.rest()));
        else if (keyword == "mtllib") read_material_libraries(words.rest());
    }

    // x y z; what follows (a vertex's w or colour) does not place it.
    glm::vec3 coordinates(TextWords& words, const char* what) const {
        glm::vec3 v;
        for (int k = 0; k < 3; ++k) {
            const std::string_view word = words.next();
            if (word.empty()) fail(std::string("a ") + what + " needs 3 coordinates, got " + std::to_string(k));
            double value = 0.0;
            if (!parse_real(word, value))
                fail(std::string(what) + " coordinate \"" + std::string(word) + "\" is not a number");
            v[k] = float(value);
            if (!std::isfinite(v[k]))
                fail(std::string(what) + " coordinate \"" + std::string(word) + "\" is not finite" +
                     (std::isfinite(value) ? " in float" : ""));
        }
        return v;
    }

    // u [v [w]]: v flipped, as OBJ's v = 0 is the image's bottom row and ours its top.
    void texture_coordinate(TextWords& words) {
        glm::vec2 t(0.0f);
        for (int k = 0; k < 2; ++k) {
            const std::string_view word = words.next();
            if (word.empty()) {
                if (k == 0) fail("a texture coordinate needs at least 1 number, got 0");
                break;
            }
            double value = 0.0;
            if (!parse_real(word, value) || !std::isfinite(float(value)))
                fail("texture coordinate \"" + std::string(word) + "\" is not a finite number");
            t[k] = float(value);
        }
        file_uvs_.push_back(glm::vec2(t.x, 1.0f - t.y));
    }

    // OBJ counts from 1; a negative index counts back from the last element defined so far.
    // Returns the 0-based index, which may be past the elements defined so far.
    int64_t resolve(std::string_view word, std::size_t defined, const char* what) const {
        int64_t raw = 0;
        switch (parse_integer(word, raw)) {
        case IntegerWord::ok: break;
        case IntegerWord::out_of_range: fail(std::string(what) + " index " + std::string(word) + " out of range");
        case IntegerWord::not_an_integer:
            fail(std::string(what) + " index \"" + std::string(word) + "\" is not an integer");
        }
        if (raw == 0) fail(std::string(what) + " index 0 (OBJ counts from 1)");
        const int64_t index = raw > 0 ? raw - 1 : int64_t(defined) + raw;
        if (index < 0)
            fail(std::string(what) + " index " + std::to_string(raw) + " reaches before the first (" +
                 std::to_string(defined) + " defined so far)");
        return index;
    }

    // A corner's normal or texture coordinate index, which must name one defined above it; -1
    // for none (an empty word). `defined_so_far` ends the message.
    int32_t defined_index(std::string_view word, std::size_t defined, const char* what, const char* defined_so_far) const {
        if (word.empty()) return -1;
        const int64_t i = resolve(word, defined, what);
        if (uint64_t(i) >= defined)
            fail(std::string(what) + " index " + std::string(word) + " out of range (" + std::to_string(defined) + " " +
                 defined_so_far + ")");
        return int32_t(i);
    }

    // Corners v, v/vt, v/vt/vn or v//vn.
    void face(TextWords& words) {
        polygon_.clear();
        polygon_normals_.clear();
        polygon_uvs_.clear();
        for (std::string_view corner = words.next(); !corner.empty(); corner = words.next()) {
            const std::size_t slash = corner.find('/');
            const std::string_view v = corner.substr(0, slash);
            std::string_view vt, vn;
            if (slash != std::string_view::npos) {
                const std::string_view after = corner.substr(slash + 1);
                const std::size_t second = after.find('/');
                vt = after.substr(0, second);
                if (second != std::string_view::npos) {
                    vn = after.substr(second + 1);
                    if (vn.empty() || vn.find('/') != std::string_view::npos)
                        fail("face corner \"" + std::string(corner) + "\" is not v, v/vt, v/vt/vn or v//vn");
                }
            }
            const int64_t vertex = resolve(v, mesh_.positions.size(), "vertex");
            // Positive indices may name vertices defined further down; checked at the end.
            if (uint64_t(vertex) >= mesh_.positions.size()) forward_references_.push_back({line_, vertex + 1});
            const int32_t uv = defined_index(vt, file_uvs_.size(), "texture coordinate", "defined so far");
            const int32_t normal = defined_index(vn, file_normals_.size(), "normal", "normals defined so far");
            polygon_.push_back(uint32_t(vertex));
            polygon_normals_.push_back(normal);
            polygon_uvs_.push_back(uv);
        }
        if (polygon_.size() < 3) fail("a face needs at least 3 vertices, got " + std::to_string(polygon_.size()));
        for (std::size_t k = 1; k + 1 < polygon_normals_.size(); ++k)
            corner_normals_.insert(corner_normals_.end(), {polygon_normals_[0], polygon_normals_[k], polygon_normals_[k + 1]});
        for (std::size_t k = 1; k + 1 < polygon_uvs_.size(); ++k)
            corner_uvs_.insert(corner_uvs_.end(), {polygon_uvs_[0], polygon_uvs_[k], polygon_uvs_[k + 1]});
        append_polygon_fan(polygon_, mesh_.triangles);
        mesh_.triangle_materials.resize(mesh_.triangles.size(), material_);
    }

    void use_material(const std::string& name) {
        const auto it = material_ids_.find(name);
        material_ = it == material_ids_.end() ? ImportedMesh::kNoMaterial : uint32_t(it->second);
        any_material_ |= it != material_ids_.end();
        if (it == material_ids_.end() && unknown_materials_.insert(name).second)
            note("usemtl " + name + ": no such material in the .mtl files");
    }

    // File names separated by blanks; "\ " is a blank inside a name. Each file is read once.
    void read_material_libraries(std::string_view names) {
        std::vector<std::string> files(1);
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (names[i] == '\\' && i + 1 < names.size()) files.back() += names[++i];
            else if (!is_blank(names[i])) files.back() += names[i];
            else if (!files.back().empty()) files.emplace_back();
        }
        if (files.back().empty()) files.pop_back();
        if (files.empty()) note("mtllib names no file");
        for (const std::string& file : files) {
            if (!material_files_.insert(file).second) continue;
            const std::string problem = read_mtl_file((base_dir_ / file).string(), materials_, material_ids_);
            if (!problem.empty()) note("mtllib " + file + ": not read (" + problem + "), its materials are missing");
        }
    }

    void finish() {
        for (const auto& [line, index] : forward_references_)
            if (uint64_t(index) > mesh_.positions.size())
                fail_at(line, "vertex index " + std::to_string(index) + " out of range (the file has " +
                                  std::to_string(mesh_.positions.size()) + " vertices)");
        // File normals only if every face corner names one: a mesh half smooth and half flat
        // would have no consistent shading normal to give its flat half.
        const bool every_corner_has_normal =
            !file_normals_.empty() && std::find(corner_normals_.begin(), corner_normals_.end(), -1) == corner_normals_.end();
        if (!file_normals_.empty() && !every_corner_has_normal)
            mesh_.notes.push_back("some faces name no vertex normal (\"vn\"): the file's normals are not used");
        if (!any_material_) mesh_.triangle_materials.clear();
        ObjTextures textures(base_dir_, mesh_.textures, use_.file_materials);
        for (const tinyobj::material_t& m : materials_) mesh_.materials.push_back(map_obj_material(m, path_, textures));

        // Texture coordinates if some corner names one and some material will read them (the
        // others get (0, 0)): without, vertices are split by normal alone, as before textures.
        const bool some_corner_has_uv =
            std::any_of(corner_uvs_.begin(), corner_uvs_.end(), [](int32_t t) { return t >= 0; });
        const bool uvs_read = use_.texture_coordinates || !mesh_.textures.empty();
        const bool uvs = some_corner_has_uv && uvs_read;
        if (every_corner_has_normal || uvs) split_vertices(every_corner_has_normal, uvs);
        std::vector<int32_t>().swap(corner_normals_);
        std::vector<int32_t>().swap(corner_uvs_);
        mesh_.pieces.push_back({0, mesh_.positions.size(), glm::dmat4(1.0)});
    }

    // One output vertex per distinct (position, normal, texture coordinate) a face corner names
    // (of those attributes kept). A position keeps its index and the file's order when its
    // corners agree (the common case), and is copied to the end once per other combination.
    void split_vertices(bool normals, bool uvs) {
        // The corner's attributes as one key: normal and coordinate indices, each + 1 (0: none).
        const auto key_of = [&](std::size_t corner) {
            const uint64_t n = normals ? uint64_t(uint32_t(corner_normals_[corner] + 1)) : 0;
            const uint64_t t = uvs ? uint64_t(uint32_t(corner_uvs_[corner] + 1)) : 0;
            return (n << 32) | t;
        };
        const auto set_attributes = [&](uint32_t v, std::size_t corner) {
            if (normals) mesh_.normals[v] = file_normals_[std::size_t(corner_normals_[corner])];
            if (uvs) mesh_.uvs[v] = corner_uvs_[corner] >= 0 ? file_uvs_[std::size_t(corner_uvs_[corner])] : glm::vec2(0.0f);
        };
        constexpr uint64_t kUnset = ~uint64_t(0);
        std::vector<uint64_t> key_of_vertex(mesh_.positions.size(), kUnset);
        std::map<std::pair<uint32_t, uint64_t>, uint32_t> copies;
        if (normals) mesh_.normals.assign(mesh_.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
        if (uvs) mesh_.uvs.assign(mesh_.positions.size(), glm::vec2(0.0f));
        for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
            for (std::size_t k = 0; k < 3; ++k) {
                uint32_t& v = mesh_.triangles[t][k];
                const std::size_t corner = 3 * t + k;
                const uint64_t key = key_of(corner);
                if (key_of_vertex[v] == kUnset || key_of_vertex[v] == key) {
                    key_of_vertex[v] = key;
                    set_attributes(v, corner);
                    continue;
                }
                const auto [it, inserted] = copies.try_emplace({v, key}, uint32_t(mesh_.positions.size()));
                if (inserted) {
                    mesh_.positions.push_back(mesh_.positions[v]);
                    if (normals) mesh_.normals.emplace_back();
                    if (uvs) mesh_.uvs.emplace_back();
                    key_of_vertex.push_back(key);
                    set_attributes(it->second, corner);
                }
                v = it->second;
            }
        }
    }

    std::string path_;
    std::filesystem::path base_dir_;
    FileBytes in_;
    uint64_t line_ = 0;
    ImportedMesh mesh_;
    std::vector<glm::vec3> file_normals_;
    std::vector<glm::vec2> file_uvs_;
    std::vector<int32_t> corner_normals_;  // per triangle corner, an index into file_normals_ or -1
    std::vector<int32_t> corner_uvs_;      // per triangle corner, an index into file_uvs_ or -1
    std::vector<std::pair<uint64_t, int64_t>> forward_references_;  // (line, 1-based index)
    std::vector<uint32_t> polygon_;
    std::vector<int32_t> polygon_normals_;
    std::vector<int32_t> polygon_uvs_;
    std::vector<tinyobj::material_t> materials_;
    std::map<std::string, int> material_ids_;
    std::unordered_set<std::string> material_files_, unknown_materials_;
    uint32_t material_ = ImportedMesh::kNoMaterial;
    bool any_material_ = false;
    MeshFileUse use_;
};

}  // namespace

ImportedMesh read_obj_file(const std::string& path, MeshFileUse use) { return ObjReader(path, use).read(); }

}  // namespace wt
