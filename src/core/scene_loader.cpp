#include "core/scene_loader.h"

#include "core/geometry_soa.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <memory>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace wt {
namespace {

// ordered_json keeps the file's key order, which fixes the material indices.
using Json = nlohmann::ordered_json;

constexpr const char* kMaterialTypes = "lambertian, oren_nayar, mirror, glass";
constexpr const char* kShapeTypes = "quad, mesh, sphere";

// ---------------------------------------------------------------------------------------------
// Field paths and value descriptions for messages

bool is_identifier(const std::string& key) {
    if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
    return std::all_of(key.begin(), key.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// "materials.white", or materials["my light"] when the key would not read as one path element.
std::string member_path(const std::string& parent, const std::string& key) {
    if (!is_identifier(key)) return parent + "[" + Json(key).dump() + "]";
    return parent.empty() ? key : parent + "." + key;
}

std::string element_path(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

std::string format_double(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::ostringstream out;
    out << v;
    return out.str();
}

std::string format_vec3(const glm::dvec3& v) {
    return "[" + format_double(v.x) + ", " + format_double(v.y) + ", " + format_double(v.z) + "]";
}

// How a value is shown after "got": short enough for one line, precise enough to find it.
std::string describe(const Json& j) {
    switch (j.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return j.dump();
    case Json::value_t::string: {
        std::string s = j.dump();
        if (s.size() > 40) s = s.substr(0, 36) + "...\"";
        return "string " + s;
    }
    case Json::value_t::number_float: {
        const double v = j.get<double>();
        return std::isfinite(v) ? j.dump() : format_double(v);
    }
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned: return j.dump();
    case Json::value_t::array: {
        if (j.empty()) return "an empty array";
        const std::string s = j.dump();
        return s.size() <= 40 ? s : "an array of " + std::to_string(j.size()) + " elements";
    }
    case Json::value_t::object: return "an object";
    default: return "a binary value";
    }
}

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
    return out;
}

// ---------------------------------------------------------------------------------------------
// Parsing the text

// nlohmann keeps only the last of repeated keys, without a word. A repeated material name would
// silently drop a material, so repeats are caught while parsing. Tracking the path also lets an
// overflowing number literal (which nlohmann reports without a position) be placed.
class ParseTracker {
public:
    bool on_event(Json::parse_event_t event, const Json& parsed, const std::string& source) {
        switch (event) {
        case Json::parse_event_t::object_start: frames_.push_back({true, {}, {}, 0}); break;
        case Json::parse_event_t::array_start: frames_.push_back({false, {}, {}, 0}); break;
        case Json::parse_event_t::key: {
            Frame& frame = frames_.back();
            const std::string key = parsed.get<std::string>();
            if (!frame.keys.insert(key).second) {
                const std::string parent = path_of_parent();
                const std::string what = parent == "materials" ? "duplicate material name " + Json(key).dump()
                                                               : "duplicate key " + Json(key).dump();
                throw SceneError(source + ": " + member_path(parent, key) + ": " + what +
                                 " (each key may appear only once in an object)");
            }
            frame.key = key;
            break;
        }
        case Json::parse_event_t::object_end:
        case Json::parse_event_t::array_end:
            frames_.pop_back();
            element_done();
            break;
        case Json::parse_event_t::value: element_done(); break;
        }
        return true;
    }

    // The path of the value being parsed right now.
    std::string current_path() const {
        std::string path;
        for (const Frame& frame : frames_)
            path = frame.is_object ? member_path(path, frame.key) : element_path(path, frame.index);
        return path;
    }

private:
    struct Frame {
        bool is_object;
        std::set<std::string> keys;  // objects: keys seen so far
        std::string key;             // objects: key of the member being parsed
        std::size_t index;           // arrays: index of the element being parsed
    };

    std::string path_of_parent() const {
        std::string path;
        for (std::size_t i = 0; i + 1 < frames_.size(); ++i)
            path = frames_[i].is_object ? member_path(path, frames_[i].key)
                                        : element_path(path, frames_[i].index);
        return path;
    }

    void element_done() {
        if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().index;
    }

    std::vector<Frame> frames_;
};

// nlohmann's line/column is that of the last character it read, which can be a newline
// ("line 2, column 0"); report the position of the offending character instead.
std::string line_and_column(const std::string& text, std::size_t byte) {
    const std::size_t offset = std::min(byte > 0 ? byte - 1 : 0, text.size());  // byte is 1-based
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            line_start = i + 1;
        }
    }
    return std::to_string(line) + ":" + std::to_string(offset - line_start + 1);
}

// "[json.exception.parse_error.101] parse error at line 2, column 8: syntax error while parsing
// value - unexpected ','" -> "while parsing value - unexpected ','"
std::string strip_nlohmann_prefix(const std::string& what) {
    std::string msg = what;
    const std::size_t colon = msg.find(": ");
    if (colon != std::string::npos) msg = msg.substr(colon + 2);
    const std::string redundant = "syntax error ";
    if (msg.compare(0, redundant.size(), redundant) == 0) msg = msg.substr(redundant.size());
    return msg;
}

Json parse_json(const std::string& text, const std::string& source) {
    ParseTracker tracker;
    const Json::parser_callback_t callback = [&](int, Json::parse_event_t event, Json& parsed) {
        return tracker.on_event(event, parsed, source);
    };
    try {
        return Json::parse(text, callback);
    } catch (const Json::parse_error& e) {
        throw SceneError(source + ":" + line_and_column(text, e.byte) +
                         ": JSON syntax error: " + strip_nlohmann_prefix(e.what()));
    } catch (const Json::out_of_range& e) {
        // A literal such as 1e999, the only out_of_range the parser raises (406): "number
        // overflow parsing '1e999'". It comes without a position, but the tracker knows the path.
        const std::string what = e.what();
        const std::size_t open = what.find('\''), close = what.rfind('\'');
        const std::string literal = open < close ? what.substr(open + 1, close - open - 1) : what;
        const std::string path = tracker.current_path();
        throw SceneError(source + ": " + (path.empty() ? "(top level)" : path) + ": must be a finite number, got " +
                         literal + " (too large for a double)");
    }
}

// ---------------------------------------------------------------------------------------------
// Reading typed values; every failure names the field

// The *_problem functions return what is wrong with a value, or "" if nothing: the field's path
// is then spelled out only for a message, which matters for meshes with millions of numbers.

// Finite and representable as a float, since that is what the renderer stores.
std::string number_problem(const Json& j) {
    if (!j.is_number()) return "expected a number, got " + describe(j);
    const double v = j.get<double>();
    if (!std::isfinite(v)) return "must be a finite number, got " + describe(j);
    if (std::fabs(v) > double(FLT_MAX)) return "is too large for a 32-bit float, got " + describe(j);
    return {};
}

// Integers must be written as integers: 64.0 or 6.4e1 for a sample count is most likely a slip.
std::string integer_problem(const Json& j, uint64_t lo, uint64_t hi) {
    const auto out_of_range = [&] {
        return "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + describe(j);
    };
    if (!j.is_number()) return "expected an integer, got " + describe(j);
    if (j.is_number_float()) {
        const double v = j.get<double>();
        // Integers beyond 2^64-1 (and below -2^63) are parsed as floats.
        const bool whole = std::isfinite(v) && v == std::floor(v);
        if (whole && (v >= 18446744073709551616.0 || v < 0.0)) return out_of_range();
        return "expected an integer (no decimal point or exponent), got " + describe(j);
    }
    if (!j.is_number_unsigned() && j.get<int64_t>() < 0) return out_of_range();
    const uint64_t v = j.get<uint64_t>();
    if (v < lo || v > hi) return out_of_range();
    return {};
}

class Reader {
public:
    explicit Reader(std::string source) : source_(std::move(source)) {}

    [[noreturn]] void fail(const std::string& path, const std::string& what) const {
        throw SceneError(source_ + ": " + (path.empty() ? "(top level)" : path) + ": " + what);
    }

    void expect_object(const Json& j, const std::string& path) const {
        if (!j.is_object()) fail(path, "expected an object, got " + describe(j));
    }

    void expect_array(const Json& j, const std::string& path) const {
        if (!j.is_array()) fail(path, "expected an array, got " + describe(j));
    }

    // A typo in an optional key would otherwise silently fall back to the default.
    void check_keys(const Json& object, const std::string& path, std::initializer_list<const char*> allowed,
                    const std::string& context = "") const {
        for (const auto& member : object.items()) {
            const bool known = std::any_of(allowed.begin(), allowed.end(),
                                           [&](const char* key) { return member.key() == key; });
            if (known) continue;
            std::vector<std::string> names(allowed.begin(), allowed.end());
            fail(member_path(path, member.key()),
                 "unknown key" + context + " (allowed: " + join(names) + ")");
        }
    }

    const Json& required(const Json& object, const char* key, const std::string& path) const {
        const auto it = object.find(key);
        if (it == object.end()) fail(member_path(path, key), "required key is missing");
        return *it;
    }

    // nullptr if absent
    const Json* optional(const Json& object, const char* key) const {
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    std::string text(const Json& j, const std::string& path) const {
        if (!j.is_string()) fail(path, "expected a string, got " + describe(j));
        return j.get<std::string>();
    }

    float number(const Json& j, const std::string& path) const {
        const std::string problem = number_problem(j);
        if (!problem.empty()) fail(path, problem);
        return float(j.get<double>());
    }

    uint64_t integer(const Json& j, const std::string& path, uint64_t lo, uint64_t hi) const {
        const std::string problem = integer_problem(j, lo, hi);
        if (!problem.empty()) fail(path, problem);
        return j.get<uint64_t>();
    }

    glm::vec3 vec3(const Json& j, const std::string& path) const {
        if (!j.is_array() || j.size() != 3) fail(path, "expected an array of 3 numbers, got " + describe(j));
        glm::vec3 v;
        for (std::size_t i = 0; i < 3; ++i) {
            const std::string problem = number_problem(j[i]);
            if (!problem.empty()) fail(element_path(path, i), problem);
            v[int(i)] = float(j[i].get<double>());
        }
        return v;
    }

    // A colour; with at_most_one, a reflectance that may not create energy.
    glm::vec3 color(const Json& j, const std::string& path, bool at_most_one) const {
        const glm::vec3 c = vec3(j, path);
        for (std::size_t i = 0; i < 3; ++i) {
            const float v = c[int(i)];
            if (at_most_one && !(v >= 0.0f && v <= 1.0f))
                fail(element_path(path, i), "must be in [0, 1], got " + describe(j[i]));
            if (!(v >= 0.0f)) fail(element_path(path, i), "must be non-negative, got " + describe(j[i]));
        }
        return c;
    }

private:
    std::string source_;
};

// ---------------------------------------------------------------------------------------------
// Sections

CameraDescription read_camera(const Reader& in, const Json& j, const std::string& path) {
    in.expect_object(j, path);
    in.check_keys(j, path, {"eye", "look_at", "up", "fov_degrees"});
    CameraDescription camera;
    camera.eye = in.vec3(in.required(j, "eye", path), member_path(path, "eye"));
    camera.look_at = in.vec3(in.required(j, "look_at", path), member_path(path, "look_at"));
    if (const Json* up = in.optional(j, "up")) camera.up = in.vec3(*up, member_path(path, "up"));
    if (const Json* fov = in.optional(j, "fov_degrees")) {
        const std::string fov_path = member_path(path, "fov_degrees");
        camera.fov_degrees = in.number(*fov, fov_path);
        if (!(camera.fov_degrees > 0.0f && camera.fov_degrees < 180.0f))
            in.fail(fov_path, "must be in (0, 180) degrees, exclusive, got " + describe(*fov));
    }

    // The camera basis is normalize(look_at - eye) and normalize(cross(forward, up)); both must exist.
    const glm::dvec3 forward = glm::dvec3(camera.look_at) - glm::dvec3(camera.eye);
    if (glm::length(forward) == 0.0)
        in.fail(member_path(path, "look_at"),
                "must differ from camera.eye, got " + format_vec3(camera.look_at) + " for both");
    const glm::dvec3 up = camera.up;
    if (glm::length(up) == 0.0) in.fail(member_path(path, "up"), "must be non-zero, got [0, 0, 0]");
    const double sine = glm::length(glm::cross(glm::normalize(forward), glm::normalize(up)));
    if (sine <= 1e-6)
        in.fail(member_path(path, "up"), "must not be parallel to the view direction (look_at - eye = " +
                                             format_vec3(forward) + "), got " + format_vec3(up));
    return camera;
}

RenderSettings read_render(const Reader& in, const Json& j, const std::string& path) {
    in.expect_object(j, path);
    in.check_keys(j, path, {"width", "height", "spp", "shadow_rays", "seed", "max_bounces", "rr_start_bounce",
                            "triangle_test", "sphere_test", "fresnel"});
    RenderSettings s;
    const auto read_int = [&](const char* key, int& field, uint64_t lo, uint64_t hi) {
        if (const Json* v = in.optional(j, key)) field = int(in.integer(*v, member_path(path, key), lo, hi));
    };
    read_int("width", s.width, 1, 65536);
    read_int("height", s.height, 1, 65536);
    read_int("spp", s.spp, 1, uint64_t(1) << 20);
    read_int("shadow_rays", s.shadow_rays, 1, 1024);
    read_int("max_bounces", s.max_bounces, 1, 1024);
    read_int("rr_start_bounce", s.rr_start_bounce, 0, INT32_MAX);
    if (const Json* seed = in.optional(j, "seed")) s.seed = in.integer(*seed, member_path(path, "seed"), 0, UINT64_MAX);
    const auto read_choice = [&](const char* key, auto& field, auto parse, const char* allowed) {
        const Json* v = in.optional(j, key);
        if (!v) return;
        const std::string key_path = member_path(path, key);
        const auto parsed = parse(in.text(*v, key_path));
        if (!parsed) in.fail(key_path, std::string("must be one of ") + allowed + ", got " + describe(*v));
        field = *parsed;
    };
    read_choice("triangle_test", s.accuracy.triangles, parse_triangle_test, "\"moller_trumbore\", \"watertight\"");
    read_choice("sphere_test", s.accuracy.spheres, parse_sphere_test, "\"quadratic\", \"cancellation_free\"");
    read_choice("fresnel", s.accuracy.fresnel, parse_fresnel_model, "\"schlick\", \"exact\"");
    return s;
}

MaterialType read_material_type(const Reader& in, const Json& j, const std::string& path) {
    const std::string type = in.text(j, path);
    if (type == "lambertian") return MaterialType::lambertian;
    if (type == "oren_nayar") return MaterialType::oren_nayar;
    if (type == "mirror") return MaterialType::mirror;
    if (type == "glass") return MaterialType::glass;
    in.fail(path, std::string("unknown material type (allowed: ") + kMaterialTypes + "), got " + describe(j));
}

Material read_material(const Reader& in, const std::string& name, const Json& j, const std::string& path) {
    in.expect_object(j, path);
    if (!j.contains("type"))
        in.fail(member_path(path, "type"), std::string("required key is missing (one of ") + kMaterialTypes + ")");
    Material m;
    m.name = name;
    m.type = read_material_type(in, j.at("type"), member_path(path, "type"));
    const std::string type_name = j.at("type").get<std::string>();

    // The renderer only samples emission on diffuse surfaces; a glowing mirror would be ignored.
    if (m.is_specular() && j.contains("emission"))
        in.fail(member_path(path, "emission"), "emission is not supported on " + type_name +
                                                   " materials (only lambertian and oren_nayar can emit)");

    const std::string context = " for a " + type_name + " material";
    switch (m.type) {
    case MaterialType::lambertian: in.check_keys(j, path, {"type", "albedo", "emission"}, context); break;
    case MaterialType::oren_nayar: in.check_keys(j, path, {"type", "albedo", "sigma", "emission"}, context); break;
    case MaterialType::mirror: in.check_keys(j, path, {"type", "reflectance"}, context); break;
    case MaterialType::glass: in.check_keys(j, path, {"type", "ior"}, context); break;
    }

    if (m.type == MaterialType::lambertian || m.type == MaterialType::oren_nayar) {
        m.albedo = in.color(in.required(j, "albedo", path), member_path(path, "albedo"), true);
        if (const Json* e = in.optional(j, "emission")) m.emission = in.color(*e, member_path(path, "emission"), false);
    }
    if (m.type == MaterialType::oren_nayar) {
        const Json& sigma = in.required(j, "sigma", path);
        m.sigma = in.number(sigma, member_path(path, "sigma"));
        if (!(m.sigma >= 0.0f)) in.fail(member_path(path, "sigma"), "must be non-negative, got " + describe(sigma));
    }
    if (m.type == MaterialType::mirror) {
        if (const Json* r = in.optional(j, "reflectance"))
            m.reflectance = in.color(*r, member_path(path, "reflectance"), true);
    }
    if (m.type == MaterialType::glass) {
        const Json& ior = in.required(j, "ior", path);
        m.ior = in.number(ior, member_path(path, "ior"));
        if (!(m.ior > 0.0f)) in.fail(member_path(path, "ior"), "must be positive, got " + describe(ior));
    }
    return m;
}

std::vector<Material> read_materials(const Reader& in, const Json& j, const std::string& path) {
    in.expect_object(j, path);
    std::vector<Material> materials;
    for (const auto& member : j.items()) {
        if (member.key().empty()) in.fail(path, "material names must not be empty");
        materials.push_back(read_material(in, member.key(), member.value(), member_path(path, member.key())));
    }
    return materials;
}

uint32_t find_material(const Reader& in, const std::vector<Material>& materials, const Json& j,
                       const std::string& path) {
    const std::string name = in.text(j, path);
    for (std::size_t i = 0; i < materials.size(); ++i)
        if (materials[i].name == name) return uint32_t(i);
    std::vector<std::string> names;
    for (const Material& m : materials) names.push_back(m.name);
    in.fail(path, "no material named " + Json(name).dump() + " (defined: " +
                      (names.empty() ? std::string("none") : join(names)) + ")");
}

// Twice the triangle's area, and its longest edge, in double so float round-off cannot hide a
// degenerate triangle.
struct TriangleSize {
    double cross_length;
    double longest_edge;
    bool degenerate() const { return cross_length <= 1e-12 * longest_edge * longest_edge; }
};

TriangleSize triangle_size(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 da(a), db(b), dc(c);
    const double longest = std::max({glm::length(db - da), glm::length(dc - db), glm::length(da - dc)});
    return {glm::length(glm::cross(db - da, dc - da)), longest};
}

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

// The light table samples emissive triangles by area and skips empty ones, so a zero-area light
// would vanish without a word; it is nearly always a wrong vertex index or coordinate.
void check_light_triangles(const Reader& in, const TriangleMesh& mesh, const std::string& path) {
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const glm::vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
        if (triangle_size(a, b, c).degenerate() || is_sliver(a, b, c))
            in.fail(element_path(member_path(path, "triangles"), t),
                    "degenerate light: emissive triangle " + std::to_string(t) + " has zero area (vertices " +
                        format_vec3(a) + ", " + format_vec3(b) + ", " + format_vec3(c) + ")");
    }
}

void read_shape(const Reader& in, const Json& j, const std::string& path, SceneDescription& scene) {
    in.expect_object(j, path);
    if (!j.contains("type"))
        in.fail(member_path(path, "type"), std::string("required key is missing (one of ") + kShapeTypes + ")");
    const std::string type_path = member_path(path, "type");
    const std::string type = in.text(j.at("type"), type_path);
    const std::string context = " for a " + type;
    if (type == "quad") in.check_keys(j, path, {"type", "vertices", "material"}, context);
    else if (type == "mesh") in.check_keys(j, path, {"type", "vertices", "triangles", "material"}, context);
    else if (type == "sphere") in.check_keys(j, path, {"type", "center", "radius", "material"}, context);
    else in.fail(type_path, std::string("unknown shape type (allowed: ") + kShapeTypes + "), got " + describe(j.at("type")));

    const std::string material_path = member_path(path, "material");
    const uint32_t material = find_material(in, scene.materials, in.required(j, "material", path), material_path);
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
    if (m.is_emissive()) check_light_triangles(in, mesh, path);
    scene.meshes.push_back(std::move(mesh));
}

void read_shapes(const Reader& in, const Json& j, const std::string& path, SceneDescription& scene) {
    in.expect_array(j, path);
    if (j.empty()) in.fail(path, "a scene needs at least one shape, got an empty array");
    for (std::size_t i = 0; i < j.size(); ++i) read_shape(in, j[i], element_path(path, i), scene);
}

}  // namespace

SceneDescription parse_scene_json(const std::string& text, const std::string& source_name) {
    const Json root = parse_json(text, source_name);
    const Reader in(source_name);
    in.expect_object(root, "");
    in.check_keys(root, "", {"camera", "render", "materials", "shapes"});

    SceneDescription scene;
    // Fixed order, whatever the file's: shapes need the materials.
    scene.camera = read_camera(in, in.required(root, "camera", ""), "camera");
    if (const Json* render = in.optional(root, "render")) scene.settings = read_render(in, *render, "render");
    scene.materials = read_materials(in, in.required(root, "materials", ""), "materials");
    read_shapes(in, in.required(root, "shapes", ""), "shapes", scene);
    return scene;
}

SceneDescription load_scene_file(const std::string& path) {
    // C stdio rather than ifstream: fopen reliably sets errno, which makes the message useful.
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) throw SceneError(path + ": cannot open: " + std::strerror(errno));
    std::string text;
    char buffer[1 << 16];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) text.append(buffer, n);
    if (std::ferror(file.get())) throw SceneError(path + ": cannot read: " + std::strerror(errno));
    return parse_scene_json(text, path);
}

}  // namespace wt
