#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "core/scene_file/scene_schema.h"

// A shape's "transform": a 4x4 matrix, or scale, rotate and translate applied in that order.

namespace wt {
namespace {

glm::dvec3 read_scale(const Reader& in, const Json& j, const std::string& path) {
    glm::dvec3 s;
    if (j.is_number()) s = glm::dvec3(in.number(j, path));
    else s = in.vec3(j, path);
    for (int k = 0; k < 3; ++k)
        if (s[k] == 0.0) in.fail(path, "must be non-zero (a zero scale flattens the mesh), got " + describe(j));
    return s;
}

glm::dmat4 read_rotation(const Reader& in, const Json& j, const std::string& path) {
    in.expect_object(j, path);
    in.check_keys(j, path, {"axis", "degrees"});
    const std::string axis_path = member_path(path, "axis");
    const glm::dvec3 axis = in.vec3(in.required(j, "axis", path), axis_path);
    if (glm::length(axis) == 0.0) in.fail(axis_path, "must be non-zero, got [0, 0, 0]");
    const double degrees = in.number(in.required(j, "degrees", path), member_path(path, "degrees"));
    // Right-handed: counter-clockwise looking down the axis towards the origin.
    return glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::normalize(axis));
}

// Four rows of four numbers, as a matrix is written on paper; the last row must be 0 0 0 1.
glm::dmat4 read_matrix(const Reader& in, const Json& j, const std::string& path) {
    if (!j.is_array() || j.size() != 4) in.fail(path, "expected 4 rows of 4 numbers, got " + describe(j));
    glm::dmat4 m(1.0);
    for (std::size_t r = 0; r < 4; ++r) {
        const std::string row_path = element_path(path, r);
        if (!j[r].is_array() || j[r].size() != 4) in.fail(row_path, "expected a row of 4 numbers, got " + describe(j[r]));
        for (std::size_t c = 0; c < 4; ++c) m[int(c)][int(r)] = in.number(j[r][c], element_path(row_path, c));
    }
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
        in.fail(element_path(path, 3), "the last row must be [0, 0, 0, 1] (an affine transform), got " + describe(j[3]));
    const glm::dmat3 linear(m);
    const double scale = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    if (!(std::fabs(glm::determinant(linear)) > 1e-12 * scale))
        in.fail(path, "is singular (its upper 3x3 has determinant " + format_double(glm::determinant(linear)) +
                          "): it would flatten the mesh");
    return m;
}

}  // namespace

glm::dmat4 read_transform(const Reader& in, const Json& j, const std::string& path) {
    in.expect_object(j, path);
    if (const Json* matrix = in.optional(j, "matrix")) {
        in.check_keys(j, path, {"matrix"}, " next to \"matrix\" (give either a matrix or scale/rotate/translate)");
        return read_matrix(in, *matrix, member_path(path, "matrix"));
    }
    in.check_keys(j, path, {"scale", "rotate", "translate", "matrix"});
    glm::dmat4 m(1.0);
    if (const Json* t = in.optional(j, "translate"))
        m = glm::translate(m, glm::dvec3(in.vec3(*t, member_path(path, "translate"))));
    if (const Json* r = in.optional(j, "rotate")) m *= read_rotation(in, *r, member_path(path, "rotate"));
    if (const Json* s = in.optional(j, "scale")) m = glm::scale(m, read_scale(in, *s, member_path(path, "scale")));
    return m;  // T * R * S: scale first, then rotate, then translate
}

}  // namespace wt
