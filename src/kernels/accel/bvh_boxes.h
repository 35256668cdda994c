#pragma once
// Axis-aligned boxes for the BVH builder, and how far to pad them so the traversal never
// rejects a box whose primitive the flat kernels would hit.

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec3.hpp>

namespace wt {

struct Box {
    float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                   std::numeric_limits<float>::infinity()};
    float hi[3] = {-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                   -std::numeric_limits<float>::infinity()};

    void extend(const Box& b) {
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], b.lo[a]), hi[a] = std::max(hi[a], b.hi[a]);
    }
    void extend_point(const glm::vec3& p) {
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
    }
    bool empty() const { return !(lo[0] <= hi[0]); }
    glm::vec3 center() const { return {0.5f * (lo[0] + hi[0]), 0.5f * (lo[1] + hi[1]), 0.5f * (lo[2] + hi[2])}; }
    // Half the surface area: the SAH only ever compares areas.
    float half_area() const {
        if (empty()) return 0.0f;
        const float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
        return dx * dy + dy * dz + dz * dx;
    }
    Box padded(float pad) const {
        Box b;
        for (int a = 0; a < 3; ++a) b.lo[a] = lo[a] - pad, b.hi[a] = hi[a] + pad;
        return b;
    }
};

// The primitive tests compute a hit from v0 - o and products of edges, each rounded: the point
// they accept can lie outside the primitive's exact box by a few units of rounding of the
// coordinates and distances involved, which are bounded by the scene's extent, its distance from
// the origin and the camera's. A box padded by 2^-18 of that (64 float steps of it, far more
// than the few the tests lose) contains every such point, and the ray-box test itself is made
// conservative by Ize's factor ("Robust BVH Ray Traversal", JCGT 2013) in the traversal. The
// pad is a size, not an epsilon per box, so a box is never padded by less than its coordinates
// can resolve.
inline float rounding_pad(const Box& scene, const glm::vec3& eye) {
    float magnitude = 0.0f;
    for (int a = 0; a < 3; ++a) {
        magnitude = std::max({magnitude, std::fabs(scene.lo[a]), std::fabs(scene.hi[a]), std::fabs(eye[a]),
                              scene.hi[a] - scene.lo[a]});
    }
    return magnitude * 0x1p-18f;
}

}  // namespace wt
