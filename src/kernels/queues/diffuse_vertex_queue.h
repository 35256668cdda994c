#pragma once
// The flat diffuse vertices of one shade stage whose next direction is still to be drawn: what
// continue_path (core/path/path_vertex.h) reads at such a vertex, with its three random numbers
// already drawn. The shade loop fills it (shade_queue.h) and the diffuse continuation kernel
// (kernels/shading/diffuse_continuation.h) empties it N lanes at a time into the next ray queue.
// Most vertices of most scenes are of this kind, and drawing their directions one at a time
// was a fifth of a render: a dependent chain of divisions and square roots per path.

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/base/aligned_vector.h"
#include "core/materials/bsdf.h"
#include "core/scene/scene.h"

namespace wt {

// Whether continue_path's work at a vertex is the kernel's: a Lambertian or Oren-Nayar material
// on a surface without a shading normal (the folded BSDF about one stays scalar).
inline bool continues_as_flat_diffuse(const Material& m, const SurfacePoint& surface) {
    return (m.type == MaterialType::lambertian || m.type == MaterialType::oren_nayar) && !surface.smooth;
}

// What continue_path's choices at one bounce come to for every flat diffuse vertex of it.
struct DiffuseContinuation {
    bool roulette;  // Russian roulette at this bounce (bounce >= rr_start_bounce)
    bool mis;       // the estimator's mis: the next ray carries its pdf and counts the emission it finds
    // The vertex hands the paths ending specular -> light on to the light paths (light tracing at
    // the first hit, photons after it): PathContinuation::specular_light_elsewhere.
    bool specular_light_elsewhere;
};

struct DiffuseVertexQueue {
    // The kernel loads whole vectors: this many entries past `count` are allocated, and what they
    // hold is computed and thrown away.
    static constexpr std::size_t kPadding = 16;

    AlignedVector<float> px, py, pz;              // SurfacePoint::position
    AlignedVector<float> ex, ey, ez;              // SurfacePoint::error
    AlignedVector<float> nx, ny, nz;              // SurfacePoint::normal (geometric)
    AlignedVector<float> dx, dy, dz;              // the incoming ray's direction
    AlignedVector<float> throughput_r, throughput_g, throughput_b;
    AlignedVector<float> albedo_r, albedo_g, albedo_b;
    AlignedVector<float> oren_nayar_a, oren_nayar_b;  // oren_nayar_terms(); 1 and 0 for Lambertian vertices
    AlignedVector<float> u0, u1, roulette;            // dim::bsdf_u, dim::bsdf_v, dim::roulette
    AlignedVector<uint32_t> path;                     // slot in the PathTable
    // kOrenNayar; kSpecularLightElsewhere: the incoming ray's PathContinuation::specular_light_elsewhere.
    AlignedVector<uint8_t> flags;
    static constexpr uint8_t kOrenNayar = 1, kSpecularLightElsewhere = 2;
    std::size_t count = 0;

    void reserve(std::size_t n) {
        for (auto* a : {&px, &py, &pz, &ex, &ey, &ez, &nx, &ny, &nz, &dx, &dy, &dz, &throughput_r, &throughput_g, &throughput_b,
                        &albedo_r, &albedo_g, &albedo_b, &oren_nayar_a, &oren_nayar_b, &u0, &u1, &roulette})
            a->resize(n + kPadding);
        path.resize(n + kPadding), flags.resize(n + kPadding);
    }

    // Bytes per entry, for WavefrontWorkspace::bytes_needed.
    static constexpr std::size_t kBytesPerEntry = 23 * 4 + 4 + 1;

    void push(const SurfacePoint& s, const Material& m, const glm::vec3& d, const glm::vec3& throughput, float bsdf_u,
              float bsdf_v, float roulette_u, uint32_t slot, bool specular_light_elsewhere) {
        const std::size_t i = count++;
        px[i] = s.position.x, py[i] = s.position.y, pz[i] = s.position.z;
        ex[i] = s.error.x, ey[i] = s.error.y, ez[i] = s.error.z;
        nx[i] = s.normal.x, ny[i] = s.normal.y, nz[i] = s.normal.z;
        dx[i] = d.x, dy[i] = d.y, dz[i] = d.z;
        throughput_r[i] = throughput.x, throughput_g[i] = throughput.y, throughput_b[i] = throughput.z;
        albedo_r[i] = m.albedo.x, albedo_g[i] = m.albedo.y, albedo_b[i] = m.albedo.z;
        const bool oren_nayar = m.type == MaterialType::oren_nayar;
        const OrenNayarTerms terms = oren_nayar ? oren_nayar_terms(m.sigma) : OrenNayarTerms{1.0f, 0.0f};
        oren_nayar_a[i] = terms.a, oren_nayar_b[i] = terms.b;
        u0[i] = bsdf_u, u1[i] = bsdf_v, roulette[i] = roulette_u;
        path[i] = slot;
        flags[i] = uint8_t((oren_nayar ? kOrenNayar : 0) | (specular_light_elsewhere ? kSpecularLightElsewhere : 0));
    }
};

}  // namespace wt
