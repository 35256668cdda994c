// PLY (Turk 1994; the format as Paul Bourke documents it): a text header, then the elements'
// records in ASCII or binary of either byte order. Read in one pass through a fixed buffer, so
// every message can name the line (ASCII) or byte offset (binary) of the record at fault.
// Our own reader rather than assimp's: see README.md, Dependencies.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>

#include "core/import/file_bytes.h"
#include "core/import/mesh_file.h"
#include "core/import/polygon_fan.h"

namespace wt {
namespace {

enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };

enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::float32;  // for a list: the type of its items
    bool is_list = false;
    PlyType count_type = PlyType::uint8;
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyHeader {
    PlyFormat format = PlyFormat::ascii;
    std::vector<PlyElement> elements;
};

bool parse_type(const std::string& word, PlyType& type) {
    static const struct { const char* name; PlyType type; } kTypes[] = {
        {"char", PlyType::int8},     {"int8", PlyType::int8},       {"uchar", PlyType::uint8},
        {"uint8", PlyType::uint8},   {"short", PlyType::int16},     {"int16", PlyType::int16},
        {"ushort", PlyType::uint16}, {"uint16", PlyType::uint16},   {"int", PlyType::int32},
        {"int32", PlyType::int32},   {"uint", PlyType::uint32},     {"uint32", PlyType::uint32},
        {"float", PlyType::float32}, {"float32", PlyType::float32}, {"double", PlyType::float64},
        {"float64", PlyType::float64}};
    for (const auto& t : kTypes)
        if (word == t.name) {
            type = t.type;
            return true;
        }
    return false;
}

std::size_t type_size(PlyType t) {
    switch (t) {
    case PlyType::int8: case PlyType::uint8: return 1;
    case PlyType::int16: case PlyType::uint16: return 2;
    case PlyType::int32: case PlyType::uint32: case PlyType::float32: return 4;
    case PlyType::float64: return 8;
    }
    return 0;
}

bool is_integer_type(PlyType t) { return t != PlyType::float32 && t != PlyType::float64; }

// The values an integer type holds: an ASCII file can write any number in any column, and a
// list length or an index beyond its declared type would reach integer conversions unchecked.
bool fits_integer_type(PlyType t, double v) {
    switch (t) {
    case PlyType::int8: return v >= -128.0 && v <= 127.0;
    case PlyType::uint8: return v >= 0.0 && v <= 255.0;
    case PlyType::int16: return v >= -32768.0 && v <= 32767.0;
    case PlyType::uint16: return v >= 0.0 && v <= 65535.0;
    case PlyType::int32: return v >= -2147483648.0 && v <= 2147483647.0;
    case PlyType::uint32: return v >= 0.0 && v <= 4294967295.0;
    case PlyType::float32: case PlyType::float64: return true;
    }
    return false;
}

// A value for a message: exact for integers, else as %g (a float-typed index may be 1e30 or NaN,
// which no integer conversion may be asked to hold).
std::string number_text(double v) {
    if (v == std::floor(v) && std::fabs(v) < 0x1p53) return std::to_string(int64_t(v));
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

const char* type_name(PlyType t) {
    switch (t) {
    case PlyType::int8: return "char";
    case PlyType::uint8: return "uchar";
    case PlyType::int16: return "short";
    case PlyType::uint16: return "ushort";
    case PlyType::int32: return "int";
    case PlyType::uint32: return "uint";
    case PlyType::float32: return "float";
    case PlyType::float64: return "double";
    }
    return "?";
}

const std::string kNoElement = "(no element)";

// Reads the records of one file; `where()` names the current record for messages.
class PlyReader {
public:
    explicit PlyReader(const std::string& path) : path_(path), in_(path) {}

    ImportedMesh read() {
        read_header();
        ImportedMesh mesh;
        if (skipped_header_lines_ > 0) mesh.notes.push_back(skipped_header_note());
        mesh.pieces.push_back({});
        for (const PlyElement& element : header_.elements) read_element(element, mesh);
        mesh.pieces[0].vertex_count = mesh.positions.size();
        if (mesh.positions.empty()) fail_at_file("the file has no vertices (an empty mesh)");
        if (!has_normals_) mesh.normals.clear();
        return mesh;
    }

private:
    [[noreturn]] void fail_at_file(const std::string& what) const { throw MeshFileError(path_ + ": " + what); }

    [[noreturn]] void fail(const std::string& what) const { throw MeshFileError(where() + ": " + what); }

    std::string where() const {
        if (header_.format == PlyFormat::ascii || in_header_) return path_ + ":" + std::to_string(line_);
        return path_ + ": byte " + std::to_string(record_offset_) + " (" + record_name() + ")";
    }

    void read_header() {
        std::string line;
        const auto next = [&]() {
            if (!in_.read_line(line)) fail("the header ends before end_header");
            ++line_;
        };
        next();
        if (line != "ply") fail("not a PLY file: the first line must be \"ply\"");
        bool have_format = false;
        for (;;) {
            next();
            std::istringstream words(line);
            std::string keyword;
            words >> keyword;
            if (keyword == "end_header") break;
            if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
            if (keyword == "format") {
                std::string format, version;
                words >> format >> version;
                if (format == "ascii") header_.format = PlyFormat::ascii;
                else if (format == "binary_little_endian") header_.format = PlyFormat::binary_little_endian;
                else if (format == "binary_big_endian") header_.format = PlyFormat::binary_big_endian;
                else fail("unknown format \"" + format + "\" (allowed: ascii, binary_little_endian, binary_big_endian)");
                if (version != "1.0") fail("unsupported PLY version \"" + version + "\" (only 1.0)");
                have_format = true;
            } else if (keyword == "element") {
                PlyElement element;
                long long count = -1;
                words >> element.name >> count;
                if (element.name.empty() || words.fail() || count < 0) fail("malformed element line: \"" + line + "\"");
                element.count = uint64_t(count);
                header_.elements.push_back(element);
            } else if (keyword == "property") {
                if (header_.elements.empty()) fail("property before the first element: \"" + line + "\"");
                PlyProperty p;
                std::string type;
                words >> type;
                if (type == "list") {
                    std::string count_type, item_type;
                    words >> count_type >> item_type;
                    p.is_list = true;
                    if (!parse_type(count_type, p.count_type) || !is_integer_type(p.count_type) ||
                        !parse_type(item_type, p.type))
                        fail("malformed list property: \"" + line + "\"");
                } else if (!parse_type(type, p.type)) {
                    fail("unknown property type \"" + type + "\"");
                }
                words >> p.name;
                if (p.name.empty()) fail("property without a name: \"" + line + "\"");
                header_.elements.back().properties.push_back(p);
            } else {
                // Not PLY (Blender 2.4's "Created by ..."): skipped, as assimp and Blender's own
                // reader do, and said in a note, in case it was meant as a line of the layout.
                if (skipped_header_lines_++ == 0) first_skipped_ = {line_, line};
            }
        }
        if (!have_format) fail("the header has no format line");
        in_header_ = false;
        for (const PlyElement& e : header_.elements)
            if (e.name == "vertex") vertex_count_ = e.count;
        if (vertex_count_ > UINT32_MAX) fail("more than 2^32 - 1 vertices");
    }

    std::string skipped_header_note() const {
        std::string text = first_skipped_.second;
        if (text.size() > 80) text = text.substr(0, 77) + "...";
        const std::string where = "line " + std::to_string(first_skipped_.first) + ": \"" + text + "\"";
        if (skipped_header_lines_ == 1) return "skipped a header line that is not PLY, " + where;
        return "skipped " + std::to_string(skipped_header_lines_) + " header lines that are not PLY, the first " + where;
    }

    // One value of the current record, as double (exact for every PLY integer type).
    double value(PlyType type) {
        if (header_.format == PlyFormat::ascii) return ascii_value(type);
        switch (type) {
        case PlyType::int8: return binary_value<int8_t>();
        case PlyType::uint8: return binary_value<uint8_t>();
        case PlyType::int16: return binary_value<int16_t>();
        case PlyType::uint16: return binary_value<uint16_t>();
        case PlyType::int32: return binary_value<int32_t>();
        case PlyType::uint32: return binary_value<uint32_t>();
        case PlyType::float32: return binary_value<float>();
        case PlyType::float64: return binary_value<double>();
        }
        return 0.0;
    }

    // One binary value of type T: read with a size known at compile time, so that a file of
    // millions of records is read at memory speed rather than a library call per value.
    template <typename T>
    double binary_value() {
        unsigned char bytes[sizeof(T)];
        if (!in_.read(bytes, sizeof(T)))
            fail("the file ends inside this record (" + std::to_string(in_.size()) + " bytes in the file)");
        // The host is little-endian (x86-64, AArch64 as Debian runs them).
        if (header_.format == PlyFormat::binary_big_endian) std::reverse(bytes, bytes + sizeof(T));
        T v;
        std::memcpy(&v, bytes, sizeof(T));
        return double(v);
    }

    double ascii_value(PlyType type) {
        while (*cursor_ == ' ' || *cursor_ == '\t') ++cursor_;
        if (*cursor_ == '\0') fail("too few values on this line for element \"" + record_name() + "\"");
        char* end = nullptr;
        const double v = std::strtod(cursor_, &end);
        const std::string token(cursor_, std::strcspn(cursor_, " \t"));
        if (end == cursor_ || (*end != '\0' && *end != ' ' && *end != '\t')) fail("not a number: \"" + token + "\"");
        if (is_integer_type(type) && !(v == std::floor(v))) fail("expected an integer, got \"" + token + "\"");
        if (!fits_integer_type(type, v))
            fail("\"" + token + "\" is out of range for its type, " + type_name(type));
        cursor_ = end;
        return v;
    }

    // The element and index of the current record, named only when a message needs them.
    std::string record_name() const { return *record_element_ + " " + std::to_string(record_index_); }

    void begin_record(const std::string& name, uint64_t index) {
        record_element_ = &name;
        record_index_ = index;
        if (header_.format != PlyFormat::ascii) {
            record_offset_ = in_.offset();
            return;
        }
        do {  // blank lines between records are tolerated
            if (!in_.read_line(line_buffer_)) fail("the file ends before " + record_name());
            ++line_;
        } while (line_buffer_.find_first_not_of(" \t") == std::string::npos);
        cursor_ = line_buffer_.c_str();
    }

    void end_record() {
        if (header_.format != PlyFormat::ascii) return;
        while (*cursor_ == ' ' || *cursor_ == '\t') ++cursor_;
        if (*cursor_ != '\0') fail("extra values at the end of the line: \"" + std::string(cursor_) + "\"");
    }

    void read_element(const PlyElement& element, ImportedMesh& mesh) {
        const bool is_vertex = element.name == "vertex", is_face = element.name == "face";
        int xyz[3] = {-1, -1, -1}, nxyz[3] = {-1, -1, -1}, indices = -1;
        for (int i = 0; i < int(element.properties.size()); ++i) {
            const PlyProperty& p = element.properties[std::size_t(i)];
            for (int k = 0; k < 3; ++k) {
                if (p.name == std::string(1, char('x' + k))) xyz[k] = i;
                if (p.name == "n" + std::string(1, char('x' + k))) nxyz[k] = i;
            }
            if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) indices = i;
        }
        if (is_vertex) {
            if (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0) fail_at_file("the vertex element lacks an x, y or z property");
            has_normals_ = nxyz[0] >= 0 && nxyz[1] >= 0 && nxyz[2] >= 0;
            // Never trust a count for an allocation before the bytes are there to back it.
            const uint64_t cap = in_.size() / 4;
            mesh.positions.reserve(std::size_t(std::min(element.count, cap)));
            if (has_normals_) mesh.normals.reserve(std::size_t(std::min(element.count, cap)));
        }
        if (is_face && indices < 0) fail_at_file("the face element has no vertex_indices list");
        if (is_face) {  // a face is at least one triangle: reserved up to what the file's bytes can hold
            const uint64_t cap = in_.size() / smallest_record_bytes(element, indices);
            mesh.triangles.reserve(mesh.triangles.size() + std::size_t(std::min(element.count, cap)));
        }

        double values[16];
        std::vector<uint32_t> polygon;
        for (uint64_t r = 0; r < element.count; ++r) {
            begin_record(element.name, r);
            for (int i = 0; i < int(element.properties.size()); ++i) {
                const PlyProperty& p = element.properties[std::size_t(i)];
                if (!p.is_list) {
                    const double v = value(p.type);
                    if (i < 16) values[i] = v;
                    continue;
                }
                const double count = value(p.count_type);
                if (count < 0) fail("negative list length " + std::to_string(int64_t(count)));
                if (i != indices || !is_face) {
                    for (uint64_t k = 0; k < uint64_t(count); ++k) value(p.type);
                    continue;
                }
                if (count < 3) fail("a face needs at least 3 vertices, got " + std::to_string(int64_t(count)));
                polygon.clear();
                for (uint64_t k = 0; k < uint64_t(count); ++k) {
                    const double index = value(p.type);
                    if (!(index >= 0 && index < double(vertex_count_)))
                        fail("vertex index " + number_text(index) + " out of range (the file has " +
                             std::to_string(vertex_count_) + " vertices)");
                    polygon.push_back(uint32_t(index));
                }
                append_polygon_fan(polygon, mesh.triangles);
            }
            end_record();
            if (is_vertex) read_vertex(values, xyz, nxyz, mesh);
        }
    }

    // The fewest bytes a record of `element` can take, its list `indices` holding at least 3
    // items: in ASCII a digit and a separator a value; in binary the types' sizes.
    uint64_t smallest_record_bytes(const PlyElement& element, int indices) const {
        uint64_t bytes = 0;
        for (int i = 0; i < int(element.properties.size()); ++i) {
            const PlyProperty& p = element.properties[std::size_t(i)];
            const uint64_t items = i == indices ? 3 : 0;
            if (header_.format == PlyFormat::ascii) bytes += 2 * ((p.is_list ? 1 : 0) + (p.is_list ? items : 1));
            else bytes += p.is_list ? type_size(p.count_type) + items * type_size(p.type) : type_size(p.type);
        }
        return std::max<uint64_t>(bytes, 1);
    }

    void read_vertex(const double* values, const int* xyz, const int* nxyz, ImportedMesh& mesh) {
        glm::vec3 p, n;
        for (int k = 0; k < 3; ++k) {
            if (xyz[k] >= 16 || (has_normals_ && nxyz[k] >= 16)) fail("x, y, z, nx, ny, nz must be among the first 16 properties");
            p[k] = float(values[xyz[k]]);
            if (has_normals_) n[k] = float(values[nxyz[k]]);
        }
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            fail("vertex position is not finite: " + std::to_string(p.x) + " " + std::to_string(p.y) + " " +
                 std::to_string(p.z));
        mesh.positions.push_back(p);
        if (!has_normals_) return;
        if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z))
            fail("vertex normal is not finite");
        mesh.normals.push_back(n);
    }

    std::string path_;
    FileBytes in_;
    PlyHeader header_;
    bool in_header_ = true;
    uint64_t skipped_header_lines_ = 0;
    std::pair<uint64_t, std::string> first_skipped_;  // its line number and text
    bool has_normals_ = false;
    uint64_t vertex_count_ = 0;
    uint64_t line_ = 0;
    uint64_t record_offset_ = 0;
    const std::string* record_element_ = &kNoElement;
    uint64_t record_index_ = 0;
    std::string line_buffer_;
    const char* cursor_ = "";
};

}  // namespace

ImportedMesh read_ply_file(const std::string& path, MeshFileUse) { return PlyReader(path).read(); }

}  // namespace wt
