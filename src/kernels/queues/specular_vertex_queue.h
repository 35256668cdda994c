#pragma once
// A batch of flat mirror and glass vertices: what sample_specular (core/materials/bsdf.h) and
// the continuation after it read at such a vertex, its choice and roulette numbers already
// drawn. The light pass fills it with the vertices of a bounce of light paths
// (kernels/caustics/light_tracing_pass.cpp), the shade stage with its camera paths'
// (kernels/wavefront/shade_queue.h); the shade kernels (kernels/shading/specular_continuation.h)
// turn it into the next rays N lanes at a time. Every light path that counts starts at a mirror
// or glass (kernels/caustics/specular_targets.h), and one at a time a reflection or refraction
// was a dependent chain of a square root and divisions per path.

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/base/aligned_vector.h"
#include "core/scene/scene.h"
#include "kernels/queues/kernel_padding.h"

namespace wt {

// Whether a vertex's continuation is the specular kernel's: a mirror or smooth glass without
// textures, at a point without a shading normal (whose folded BSDF is other code).
inline bool continues_as_specular(const Material& m, const SurfacePoint& surface) {
    return (m.type == MaterialType::mirror || m.type == MaterialType::glass) && !m.has_textures() && !surface.smooth;
}

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
    // The next ray's RayQueue flags: a camera path's count_emission and specular_light_elsewhere
    // (continue_path: a specular vertex keeps the arriving ray's), 0 for a light path.
    AlignedVector<uint8_t> next_flags;
    std::size_t count = 0;
    std::size_t capacity = 0;

    static constexpr std::size_t kBytesPerEntry = 21 * sizeof(float) + sizeof(uint32_t) + 2;

    void reserve(std::size_t n) {
        capacity = n;
        const std::size_t padded = padded_entries(n);  // (kernel_padding.h)
        for (auto* a : {&px, &py, &pz, &ex, &ey, &ez, &nx, &ny, &nz, &dx, &dy, &dz, &weight_r, &weight_g, &weight_b,
                        &reflectance_r, &reflectance_g, &reflectance_b, &ior, &choice, &roulette})
            a->resize(padded);
        path.resize(padded), glass.resize(padded), next_flags.resize(padded);
    }
    bool full() const { return count == capacity; }
    // `is_glass`: smooth glass of index `index`, else a mirror of `reflectance`.
    void push(const glm::vec3& position, const glm::vec3& error, const glm::vec3& normal, const glm::vec3& d,
              const glm::vec3& weight, bool is_glass, const glm::vec3& reflectance, float index, float u_choice,
              float u_roulette, uint32_t slot, uint8_t flags_of_next = 0) {
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
        next_flags[i] = flags_of_next;
    }
};

}  // namespace wt
