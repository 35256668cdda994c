#include "mesh_writers.h"

#include <charconv>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include "atomic_file.h"

namespace wt::bench {

namespace {

// Little-endian bytes whatever the host's byte order, as PLY's binary_little_endian and glTF
// require.
class LittleEndianBytes {
public:
    void u8(uint8_t value) { bytes_.push_back(value); }
    void u32(uint32_t value) {
        for (int shift = 0; shift < 32; shift += 8) bytes_.push_back(uint8_t(value >> shift));
    }
    void f32(float value) {
        uint32_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        u32(bits);
    }
    void vec3(const glm::vec3& v) { f32(v.x), f32(v.y), f32(v.z); }
    void pad_to_multiple_of_4(uint8_t fill) {
        while (bytes_.size() % 4 != 0) bytes_.push_back(fill);
    }
    std::size_t size() const { return bytes_.size(); }
    void write_to(std::ostream& out) const { out.write(reinterpret_cast<const char*>(bytes_.data()), std::streamsize(bytes_.size())); }

private:
    std::vector<uint8_t> bytes_;
};

bool has_normals(const TriangleMesh& mesh) {
    if (mesh.normals.empty()) return false;
    if (mesh.normals.size() != mesh.vertices.size())
        throw std::invalid_argument("mesh writer: " + std::to_string(mesh.normals.size()) + " normals for " +
                                    std::to_string(mesh.vertices.size()) + " vertices");
    return true;
}

// The shortest decimal that reads back as the same float (std::to_chars' guarantee).
void append_float(std::string& line, float value) {
    char digits[32];
    const auto result = std::to_chars(digits, digits + sizeof digits, value);
    line.push_back(' ');
    line.append(digits, result.ptr);
}

void append_vec3_line(std::string& text, const char* keyword, const glm::vec3& v) {
    text += keyword;
    append_float(text, v.x), append_float(text, v.y), append_float(text, v.z);
    text.push_back('\n');
}

}  // namespace

void write_ply(const std::string& path, const TriangleMesh& mesh, const std::string& comment) {
    const bool normals = has_normals(mesh);
    std::string header = "ply\nformat binary_little_endian 1.0\ncomment " + comment + "\n";
    header += "element vertex " + std::to_string(mesh.vertices.size()) + "\n";
    header += "property float x\nproperty float y\nproperty float z\n";
    if (normals) header += "property float nx\nproperty float ny\nproperty float nz\n";
    header += "element face " + std::to_string(mesh.triangles.size()) + "\n";
    header += "property list uchar uint vertex_indices\nend_header\n";
    LittleEndianBytes body;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        body.vec3(mesh.vertices[i]);
        if (normals) body.vec3(mesh.normals[i]);
    }
    for (const auto& triangle : mesh.triangles) {
        body.u8(3);
        for (uint32_t index : triangle) body.u32(index);
    }
    write_file_atomically(path, [&](std::ostream& out) {
        out << header;
        body.write_to(out);
    });
}

void write_obj(const std::string& path, const TriangleMesh& mesh, const std::string& comment) {
    const bool normals = has_normals(mesh);
    std::string text = "# " + comment + "\n";
    for (const glm::vec3& v : mesh.vertices) append_vec3_line(text, "v", v);
    if (normals)
        for (const glm::vec3& n : mesh.normals) append_vec3_line(text, "vn", n);
    for (const auto& triangle : mesh.triangles) {
        text += 'f';
        for (uint32_t index : triangle) {
            const std::string one_based = std::to_string(index + 1);
            text += ' ' + one_based;
            if (normals) text += "//" + one_based;
        }
        text += '\n';
    }
    write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

void write_glb(const std::string& path, const TriangleMesh& mesh, const std::string& generator) {
    const bool normals = has_normals(mesh);
    // The binary chunk: positions, then normals, then indices, each 4-byte aligned by size.
    LittleEndianBytes bin;
    glm::vec3 lo = mesh.vertices.at(0), hi = mesh.vertices.at(0);
    for (const glm::vec3& v : mesh.vertices) {
        bin.vec3(v);
        lo = glm::min(lo, v), hi = glm::max(hi, v);
    }
    const std::size_t vertex_bytes = 12 * mesh.vertices.size();
    if (normals)
        for (const glm::vec3& n : mesh.normals) bin.vec3(n);
    const std::size_t index_offset = bin.size();
    for (const auto& triangle : mesh.triangles)
        for (uint32_t index : triangle) bin.u32(index);
    const std::size_t index_bytes = bin.size() - index_offset;

    constexpr int kFloat = 5126, kUnsignedInt = 5125;               // glTF componentType
    constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;  // bufferView target
    using json = nlohmann::ordered_json;
    json views = json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", vertex_bytes}, {"target", kArrayBuffer}}});
    json accessors = json::array({{{"bufferView", 0}, {"componentType", kFloat}, {"count", mesh.vertices.size()},
                                   {"type", "VEC3"}, {"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}}});
    json attributes = {{"POSITION", 0}};
    if (normals) {
        views.push_back({{"buffer", 0}, {"byteOffset", vertex_bytes}, {"byteLength", vertex_bytes}, {"target", kArrayBuffer}});
        accessors.push_back({{"bufferView", 1}, {"componentType", kFloat}, {"count", mesh.normals.size()}, {"type", "VEC3"}});
        attributes["NORMAL"] = 1;
    }
    const int index_view = int(views.size());
    views.push_back({{"buffer", 0}, {"byteOffset", index_offset}, {"byteLength", index_bytes}, {"target", kElementArrayBuffer}});
    accessors.push_back({{"bufferView", index_view}, {"componentType", kUnsignedInt}, {"count", 3 * mesh.triangles.size()}, {"type", "SCALAR"}});
    constexpr int kTriangles = 4;
    const json document = {
        {"asset", {{"version", "2.0"}, {"generator", generator}}},
        {"scene", 0},
        {"scenes", json::array({{{"nodes", {0}}}})},
        {"nodes", json::array({{{"mesh", 0}}})},
        {"meshes", json::array({{{"primitives", json::array({{{"attributes", attributes}, {"indices", index_view}, {"mode", kTriangles}}})}}})},
        {"buffers", json::array({{{"byteLength", bin.size()}}})},
        {"bufferViews", views},
        {"accessors", accessors},
    };

    // GLB: a 12-byte header, then chunks of (length, type, data), each padded to 4 bytes: the
    // JSON chunk with spaces, the binary chunk with zeros.
    LittleEndianBytes json_chunk;
    for (char c : document.dump()) json_chunk.u8(uint8_t(c));
    json_chunk.pad_to_multiple_of_4(' ');
    bin.pad_to_multiple_of_4(0);
    LittleEndianBytes header;
    const std::size_t total = 12 + 8 + json_chunk.size() + 8 + bin.size();
    if (total > UINT32_MAX) throw std::runtime_error(path + ": mesh too large for one .glb file (" + std::to_string(total) + " bytes)");
    header.u32(0x46546C67);  // "glTF"
    header.u32(2);
    header.u32(uint32_t(total));
    header.u32(uint32_t(json_chunk.size()));
    header.u32(0x4E4F534A);  // "JSON"
    LittleEndianBytes bin_header;
    bin_header.u32(uint32_t(bin.size()));
    bin_header.u32(0x004E4942);  // "BIN\0"
    write_file_atomically(path, [&](std::ostream& out) {
        header.write_to(out);
        json_chunk.write_to(out);
        bin_header.write_to(out);
        bin.write_to(out);
    });
}

}  // namespace wt::bench
