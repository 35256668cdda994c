#pragma once
// A batch of flat mirror and glass vertices of light paths: what sample_specular
// (core/materials/bsdf.h) and the continuation after it read at such a vertex, its choice and
// roulette numbers already drawn. The light pass fills it with the vertices of a bounce
// (kernels/caustics/light_tracing_pass.cpp); the shade kernels
// (kernels/shading/specular_continuation.h) turn it into the next rays N lanes at a time. Every
// light path that counts starts at a mirror or glass (kernels/caustics/specular_targets.h), and
// one at a time its reflection or refraction was a dependent chain of a square root and
// divisions per path.

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/base/aligned_vector.h"
#include "kernels/queues/kernel_padding.h"

namespace wt {

struct SpecularVertexQueue {
    AlignedVector<float> px, py, pz;  // SurfacePoint::position
    AlignedVector<float> ex, ey, ez;  // SurfacePoint::error
    AlignedVector<float> nx, ny, nz;  // SurfacePoint::normal (geometric)
    AlignedVector<float> dx, dy, dz;  // the arriving ray's direction
    AlignedVector<float> weight_r, weight_g, weight_b;  // the path's weight arriving
    AlignedVector<float> reflectance_r, reflectance_g, reflectance_b;  // a mirror's
    AlignedVector<float> ior;                                         // a glass's
    AlignedVector<float> choice, roulette;  // the vertex's reflect-or-refract and roulette numbers
    AlignedVector<uint32_t> path;           // the path's slot in its batch
    AlignedVector<uint8_t> glass;           // 1: smooth glass, 0: a mirror
    std::size_t count = 0;

    static constexpr std::size_t kBytesPerEntry = 21 * sizeof(float) + sizeof(uint32_t) + 1;

    void reserve(std::size_t n) {
        const std::size_t padded = padded_entries(n);  // (kernel_padding.h)
        for (auto* a : {&px, &py, &pz, &ex, &ey, &ez, &nx, &ny, &nz, &dx, &dy, &dz, &weight_r, &weight_g, &weight_b,
                        &reflectance_r, &reflectance_g, &reflectance_b, &ior, &choice, &roulette})
            a->resize(padded);
        path.resize(padded), glass.resize(padded);
    }
    // `is_glass`: smooth glass of index `index`, else a mirror of `reflectance`.
    void push(const glm::vec3& position, const glm::vec3& error, const glm::vec3& normal, const glm::vec3& d,
              const glm::vec3& weight, bool is_glass, const glm::vec3& reflectance, float index, float u_choice,
              float u_roulette, uint32_t slot) {
        const std::size_t i = count++;
        px[i] = position.x, py[i] = position.y, pz[i] = position.z;
        ex[i] = error.x, ey[i] = error.y, ez[i] = error.z;
        nx[i] = normal.x, ny[i] = normal.y, nz[i] = normal.z;
        dx[i] = d.x, dy[i] = d.y, dz[i] = d.z;
        weight_r[i] = weight.x, weight_g[i] = weight.y, weight_b[i] = weight.z;
        reflectance_r[i] = reflectance.x, reflectance_g[i] = reflectance.y, reflectance_b[i] = reflectance.z;
        ior[i] = index;
        choice[i] = u_choice, roulette[i] = u_roulette;
        path[i] = slot;
        glass[i] = is_glass;
    }
};

}  // namespace wt
