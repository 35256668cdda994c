#pragma once
// The starts of a batch of light paths at the area lights: each path's point on a light (its
// position, rounding error and normal) and the two random numbers of its direction, drawn by
// the light pass (kernels/caustics/light_tracing_pass.cpp). The shade kernels
// (kernels/shading/area_light_rays.h) turn them into first rays N lanes at a time: the cosine
// lobe, its frame and the ray offset, one path at a time, were a dependent chain of a division,
// a square root and the octant's polynomials per path.

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/base/aligned_vector.h"
#include "kernels/queues/kernel_padding.h"

namespace wt {

struct LightPointQueue {
    AlignedVector<float> px, py, pz;  // LightSample::position
    AlignedVector<float> ex, ey, ez;  // LightSample::error
    AlignedVector<float> nx, ny, nz;  // LightSample::normal
    AlignedVector<float> u0, u1;      // the direction's random numbers
    AlignedVector<uint32_t> path;     // the path's slot in its batch
    std::size_t count = 0;

    static constexpr std::size_t kBytesPerEntry = 11 * sizeof(float) + sizeof(uint32_t);

    void reserve(std::size_t n) {
        const std::size_t padded = padded_entries(n);  // (kernel_padding.h)
        for (auto* a : {&px, &py, &pz, &ex, &ey, &ez, &nx, &ny, &nz, &u0, &u1}) a->resize(padded);
        path.resize(padded);
    }
    void push(const glm::vec3& position, const glm::vec3& error, const glm::vec3& normal, float direction_u0,
              float direction_u1, uint32_t slot) {
        const std::size_t i = count++;
        px[i] = position.x, py[i] = position.y, pz[i] = position.z;
        ex[i] = error.x, ey[i] = error.y, ez[i] = error.z;
        nx[i] = normal.x, ny[i] = normal.y, nz[i] = normal.z;
        u0[i] = direction_u0, u1[i] = direction_u1;
        path[i] = slot;
    }
};

}  // namespace wt
