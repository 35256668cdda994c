#pragma once
// A sampled next direction, as every material's sampler returns it (bsdf.h).

#include <glm/vec3.hpp>

namespace wt {

struct BsdfSample {
    glm::vec3 direction{0.0f};
    glm::vec3 weight{0.0f};  // f * |cos| / pdf, or the specular throughput
    float pdf = 0.0f;         // rough materials only: the direction's pdf, for the multiple importance weights
    bool specular = false;    // emission seen along it counts (no light sample covered it)
    bool transmitted = false; // refracted through the surface rather than reflected
    bool glossy = false;      // a rough material's lobe: neither diffuse nor specular (core/path/path_vertex.h)
    bool valid = false;
};

}  // namespace wt
