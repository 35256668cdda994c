#pragma once
// A photon: one diffuse vertex of a light path whose first bounce was a mirror or glass (the
// paths light tracing traces, kernels/caustics/light_path.h), kept for the camera paths that see
// that surface through a mirror or glass (photon_gather.h).

#include <cstdint>

#include <glm/vec3.hpp>

#include "core/base/aligned_vector.h"

namespace wt {

struct Photon {
    glm::vec3 position;
    glm::vec3 arriving;  // unit direction the light path travelled in to reach the vertex
    glm::vec3 normal;    // geometric, turned to the side the path arrived from
    // Power x weight arriving, divided by the light paths per sample (as the splats are): the
    // flux one sample's photon map carries.
    glm::vec3 power;
    uint32_t vertex;  // the surfaces the light path had hit, this one included (2 or more)
};

// A list of photons. Every photon is written before it is read (a light path's are placed by a
// sort, a grid's by its counting sort), so growing a list leaves the new photons unwritten
// rather than zeroing megabytes a sample only to overwrite them.
using PhotonList = UninitialisedVector<Photon>;

}  // namespace wt
