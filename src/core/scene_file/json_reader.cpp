#include "core/scene_file/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/scene_file/scene_error.h"

namespace wt {
namespace {

// Doubles from here on round to infinity as floats (round to nearest: FLT_MAX plus half its
// ulp, 2^128 - 2^103). Below it they round to at most FLT_MAX, so 3.4028235e38, FLT_MAX as
// printed to 8 digits (and just above it as a double), is a float.
constexpr double kFloatOverflow = 0x1.ffffffp+127;

bool is_identifier(const std::string& key) {
    if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
    return std::all_of(key.begin(), key.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

}  // namespace

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
        // More than 20 elements cannot print in 40 characters; do not print a million to find out.
        if (j.size() > 20) return "an array of " + std::to_string(j.size()) + " elements";
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

std::string number_problem(const Json& j) {
    if (!j.is_number()) return "expected a number, got " + describe(j);
    const double v = j.get<double>();
    if (!std::isfinite(v)) return "must be a finite number, got " + describe(j);
    if (std::fabs(v) >= kFloatOverflow) return "is too large for a 32-bit float, got " + describe(j);
    return {};
}

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


void Reader::fail(const std::string& path, const std::string& what) const {
    throw SceneError(source_ + ": " + (path.empty() ? "(top level)" : path) + ": " + what);
}

std::string Reader::resolve(const std::string& file) const {
    const std::filesystem::path relative(file);
    return relative.is_absolute() ? file : (std::filesystem::path(source_).parent_path() / relative).string();
}

void Reader::expect_object(const Json& j, const std::string& path) const {
    if (!j.is_object()) fail(path, "expected an object, got " + describe(j));
}

void Reader::expect_array(const Json& j, const std::string& path) const {
    if (!j.is_array()) fail(path, "expected an array, got " + describe(j));
}

void Reader::check_keys(const Json& object, const std::string& path, std::initializer_list<const char*> allowed,
                        const std::string& context) const {
    for (const auto& member : object.items()) {
        const bool known =
            std::any_of(allowed.begin(), allowed.end(), [&](const char* key) { return member.key() == key; });
        if (known) continue;
        std::vector<std::string> names(allowed.begin(), allowed.end());
        fail(member_path(path, member.key()), "unknown key" + context + " (allowed: " + join(names) + ")");
    }
}

const Json& Reader::required(const Json& object, const char* key, const std::string& path) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(member_path(path, key), "required key is missing");
    return *it;
}

const Json* Reader::optional(const Json& object, const char* key) const {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

std::string Reader::text(const Json& j, const std::string& path) const {
    if (!j.is_string()) fail(path, "expected a string, got " + describe(j));
    return j.get<std::string>();
}

float Reader::number(const Json& j, const std::string& path) const {
    const std::string problem = number_problem(j);
    if (!problem.empty()) fail(path, problem);
    return float(j.get<double>());
}

uint64_t Reader::integer(const Json& j, const std::string& path, uint64_t lo, uint64_t hi) const {
    const std::string problem = integer_problem(j, lo, hi);
    if (!problem.empty()) fail(path, problem);
    return j.get<uint64_t>();
}

glm::vec3 Reader::vec3(const Json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 3) fail(path, "expected an array of 3 numbers, got " + describe(j));
    glm::vec3 v;
    for (std::size_t i = 0; i < 3; ++i) {
        const std::string problem = number_problem(j[i]);
        if (!problem.empty()) fail(element_path(path, i), problem);
        v[int(i)] = float(j[i].get<double>());
    }
    return v;
}

glm::vec3 Reader::color(const Json& j, const std::string& path, bool at_most_one) const {
    const glm::vec3 c = vec3(j, path);
    for (std::size_t i = 0; i < 3; ++i) {
        const float v = c[int(i)];
        if (at_most_one && !(v >= 0.0f && v <= 1.0f))
            fail(element_path(path, i), "must be in [0, 1], got " + describe(j[i]));
        if (!(v >= 0.0f)) fail(element_path(path, i), "must be non-negative, got " + describe(j[i]));
    }
    return c;
}

}  // namespace wt
