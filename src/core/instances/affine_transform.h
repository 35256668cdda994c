#pragma once
// An affine map x -> L x + t in float, as an instance places its mesh, with bounds on the
// rounding of what it computes (pbrt-v4's Transform applied to a Point3fi, Pharr, Jakob &
// Humphreys 4th ed., sec. 6.8.6): a point's error grows by |L| times the error it had plus
// gamma(3) of the magnitudes summed, since each output coordinate is three products and three
// sums rounded.

#include <cmath>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/base/ray_offset.h"

namespace wt {

struct AffineTransform {
    float m[3][4];  // rows: (L row, t)

    // The matrix rounded to float once; its last row is taken to be 0 0 0 1.
    static AffineTransform of(const glm::dmat4& a) {
        AffineTransform t;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) t.m[r][c] = float(a[c][r]);
        return t;
    }

    glm::vec3 point(const glm::vec3& p) const {
        glm::vec3 out;
        for (int r = 0; r < 3; ++r) out[r] = m[r][0] * p.x + m[r][1] * p.y + m[r][2] * p.z + m[r][3];
        return out;
    }
    glm::vec3 vector(const glm::vec3& v) const {
        glm::vec3 out;
        for (int r = 0; r < 3; ++r) out[r] = m[r][0] * v.x + m[r][1] * v.y + m[r][2] * v.z;
        return out;
    }
    // Transposed linear part times n: with this transform the inverse of a placement, the
    // placement's inverse transpose, which maps normals.
    glm::vec3 transposed_vector(const glm::vec3& n) const {
        glm::vec3 out;
        for (int c = 0; c < 3; ++c) out[c] = m[0][c] * n.x + m[1][c] * n.y + m[2][c] * n.z;
        return out;
    }
    // |L| v: how an error vector v grows through the linear part.
    glm::vec3 magnitude_times(const glm::vec3& v) const {
        glm::vec3 out;
        for (int r = 0; r < 3; ++r) out[r] = std::fabs(m[r][0]) * v.x + std::fabs(m[r][1]) * v.y + std::fabs(m[r][2]) * v.z;
        return out;
    }
    // Bound on |point(p) - exact image of an exact point within `error` of p|.
    glm::vec3 point_error(const glm::vec3& p, const glm::vec3& error) const {
        const glm::vec3 translation = magnitude({m[0][3], m[1][3], m[2][3]});
        return (1.0f + rounding_gamma(3)) * magnitude_times(error) + rounding_gamma(3) * (magnitude_times(magnitude(p)) + translation);
    }
};

}  // namespace wt
