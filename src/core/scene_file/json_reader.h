#pragma once
// Reading typed values out of a parsed scene file, where every failure names the field:
// "SOURCE: JSON.PATH: problem, got VALUE". Shared by every section of the scene schema.

#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace wt {

// ordered_json keeps the file's key order, which fixes the material indices.
using Json = nlohmann::ordered_json;

// "materials.white", or materials["my light"] when the key would not read as one path element.
std::string member_path(const std::string& parent, const std::string& key);
std::string element_path(const std::string& parent, std::size_t index);

std::string format_double(double v);
std::string format_vec3(const glm::dvec3& v);
// How a value is shown after "got": short enough for one line, precise enough to find it.
std::string describe(const Json& j);
std::string join(const std::vector<std::string>& items);

// The *_problem functions return what is wrong with a value, or "" if nothing: the field's path
// is then spelled out only for a message, which matters for meshes with millions of numbers.
// Finite and representable as a float, since that is what the renderer stores.
std::string number_problem(const Json& j);
// Integers must be written as integers: 64.0 or 6.4e1 for a sample count is most likely a slip.
std::string integer_problem(const Json& j, uint64_t lo, uint64_t hi);

class Reader {
public:
    explicit Reader(std::string source) : source_(std::move(source)) {}

    // The file the messages name (the scene file's path as given).
    const std::string& source() const { return source_; }

    [[noreturn]] void fail(const std::string& path, const std::string& what) const;
    // A file the scene names (a mesh, a texture, a map, a glTF camera): relative to the scene
    // file's directory unless absolute.
    std::string resolve(const std::string& file) const;

    void expect_object(const Json& j, const std::string& path) const;
    void expect_array(const Json& j, const std::string& path) const;

    // A typo in an optional key would otherwise silently fall back to the default.
    void check_keys(const Json& object, const std::string& path, std::initializer_list<const char*> allowed,
                    const std::string& context = "") const;

    const Json& required(const Json& object, const char* key, const std::string& path) const;
    // nullptr if absent
    const Json* optional(const Json& object, const char* key) const;

    std::string text(const Json& j, const std::string& path) const;
    float number(const Json& j, const std::string& path) const;
    uint64_t integer(const Json& j, const std::string& path, uint64_t lo, uint64_t hi) const;
    glm::vec3 vec3(const Json& j, const std::string& path) const;
    // A colour; with at_most_one, a reflectance that may not create energy.
    glm::vec3 color(const Json& j, const std::string& path, bool at_most_one) const;

private:
    std::string source_;
};

}  // namespace wt
