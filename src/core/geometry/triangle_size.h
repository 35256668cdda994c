#pragma once
// Whether a triangle has zero area, judged in double so float round-off cannot hide it.

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace wt {

// Twice the triangle's area, and its longest edge.
struct TriangleSize {
    double cross_length;
    double longest_edge;
    bool degenerate() const { return cross_length <= 1e-12 * longest_edge * longest_edge; }
};

inline TriangleSize triangle_size(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 da(a), db(b), dc(c);
    const double longest = std::max({glm::length(db - da), glm::length(dc - db), glm::length(da - dc)});
    return {glm::length(glm::cross(db - da, dc - da)), longest};
}

// |cross(b - a, c - a)| in float, as the light table computes a light's area: it can be 0 (legs
// of 1e-12 square to 1e-24, whose square underflows) or infinite (legs of 1e20) where the double
// test above sees a fine triangle.
inline float float_cross_length(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    return glm::length(glm::cross(b - a, c - a));
}

}  // namespace wt
