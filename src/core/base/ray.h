#pragma once
// A ray and what the intersect stage reports about it. Directions are unit length everywhere:
// the sphere test and the shadow-ray distance rely on it.

#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

namespace wt {

struct Ray {
    glm::vec3 origin;
    glm::vec3 direction;  // unit length
};

// Primitive ids share one index space: [0, triangle count) are triangles, the rest spheres.
constexpr uint32_t kNoHit = std::numeric_limits<uint32_t>::max();

struct Hit {
    float t = std::numeric_limits<float>::infinity();
    uint32_t prim = kNoHit;
    float u = 0.0f;  // barycentrics of v1 and v2 for triangles; unused for spheres
    float v = 0.0f;

    bool found() const { return prim != kNoHit; }
};

}  // namespace wt
