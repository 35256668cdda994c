#pragma once
// What sampling a microfacet BSDF returns, in its local frame (z the macro normal, on the side
// of wo): the direction, f |cos_i| / pdf, and the pdf itself for multiple importance sampling.

#include <glm/vec3.hpp>

namespace wt {

struct MicrofacetSample {
    glm::vec3 wi{0.0f};
    glm::vec3 weight{0.0f};  // f * |wi.z| / pdf
    float pdf = 0.0f;        // per unit solid angle of wi; positive and finite when valid
    bool transmitted = false;
    bool valid = false;
};

}  // namespace wt
