#pragma once
// A chunk of the diffuse vertices of one shade stage: what DirectLightSampler and
// continue_path (core/path/path_vertex.h) read at such a vertex, with its random numbers already
// drawn and its light samples' points already picked. The shade loop fills it
// (kernels/wavefront/shade_queue.h) and, whenever it is full and at the end, the shade kernels
// (kernels/shading) empty it N lanes at a time into the shadow queue and the next ray queue. A
// chunk rather than the whole stage: it is read back while still in the core's cache, and its
// size does not grow with the batch times the shadow rays. Most vertices of most scenes are of
// this kind, and their light samples and next directions, one at a time, were dependent chains
// of divisions and square roots per path.

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/base/aligned_vector.h"
#include "core/materials/bsdf.h"
#include "core/scene/scene.h"
#include "kernels/queues/kernel_padding.h"

namespace wt {

// Whether a vertex's light samples and continuation are the shade kernels': a Lambertian or
// Oren-Nayar material, flat or about a shading normal (the folded BSDF of
// core/materials/shading_normal_bsdf.h).
inline bool continues_as_diffuse(const Material& m) {
    return m.type == MaterialType::lambertian || m.type == MaterialType::oren_nayar;
}

// What DirectLightSampler's choices at one bounce come to for every diffuse vertex of it.
struct DiffuseLightSampling {
    uint32_t count;          // light samples per vertex (shadow rays), each weighted 1 / count
    bool mis;                // weighted against the BSDF's sampling of the same direction
    float clamp_limit;       // per channel, per sample: light_sample_clamp_limit, infinite when not clamped
};

// What continue_path's choices at one bounce come to for every diffuse vertex of it.
struct DiffuseContinuation {
    bool roulette;  // Russian roulette at this bounce (bounce >= rr_start_bounce)
    bool mis;       // the estimator's mis: the next ray carries its pdf and counts the emission it finds
    // The vertex hands the paths ending specular -> light on to the light paths (light tracing at
    // the first hit, photons after it): PathContinuation::specular_light_elsewhere.
    bool specular_light_elsewhere;
};

struct DiffuseVertexQueue {
    // The kernels load whole aligned vectors (kernel_padding.h).
    static constexpr std::size_t kPadding = kKernelPadding;

    AlignedVector<float> px, py, pz;              // SurfacePoint::position
    AlignedVector<float> ex, ey, ez;              // SurfacePoint::error
    AlignedVector<float> nx, ny, nz;              // SurfacePoint::normal (geometric)
    AlignedVector<float> snx, sny, snz;           // SurfacePoint::shading_normal, written and read only where kSmooth
    AlignedVector<float> dx, dy, dz;              // the incoming ray's direction
    AlignedVector<float> throughput_r, throughput_g, throughput_b;
    AlignedVector<float> albedo_r, albedo_g, albedo_b;
    AlignedVector<float> oren_nayar_a, oren_nayar_b;  // oren_nayar_terms(); 1 and 0 for Lambertian vertices
    AlignedVector<float> u0, u1, roulette;            // dim::bsdf_u, dim::bsdf_v, dim::roulette
    // VertexRandom::base of a vertex pushed undrawn (push_undrawn): its draws above and its light
    // samples' below are the shade kernels' (ShadeKernels::draw_diffuse_random), a chunk at once.
    AlignedVector<uint64_t> random_base;
    AlignedVector<uint32_t> path;                     // slot in the PathTable
    // kOrenNayar; kSpecularLightElsewhere: the incoming ray's PathContinuation::specular_light_elsewhere;
    // kSamplesLights: the vertex has light samples (gathers_direct_light, and the scene has lights);
    // kSmooth: SurfacePoint::smooth, its BSDF is folded about the shading normal.
    AlignedVector<uint8_t> flags;
    static constexpr uint8_t kOrenNayar = 1, kSpecularLightElsewhere = 2, kSamplesLights = 4, kSmooth = 8;
    std::size_t count = 0;
    std::size_t capacity = 0;
    // Some vertex of the chunk is smooth: the kernels' folded code runs only then, so a scene
    // without vertex normals runs the flat code alone.
    bool has_smooth = false;

    // The light samples' points (LightSample), sample-major: sample j of entry i at j * stride + i,
    // so a kernel reads sample j of N neighbouring vertices as one vector. Written for the entries
    // with kSamplesLights.
    AlignedVector<float> light_px, light_py, light_pz, light_ex, light_ey, light_ez, light_nx, light_ny, light_nz;
    AlignedVector<float> light_r, light_g, light_b, light_pdf_area;
    // The light samples' random numbers, sample-major as the points: the point's pair
    // (dim::light_u, dim::light_v) and dim::light_choice. Drawn by the kernels for undrawn vertices,
    // then turned into the points above by the kernels (ShadeKernels::pick_light_points), or by
    // pick_light_points below for a light table the kernels do not take.
    AlignedVector<float> light_u, light_v, light_choice;
    std::size_t stride = 0;

    // Vertices per chunk for this many light samples per vertex: 256 (about 40 KB with one light
    // sample), fewer as the samples grow, 16 at least: a multiple of every width.
    static constexpr std::size_t chunk_for(std::size_t light_samples_per_vertex) {
        const std::size_t by_samples = 4096 / (light_samples_per_vertex > 0 ? light_samples_per_vertex : 1) / kPadding * kPadding;
        return by_samples < kPadding ? kPadding : by_samples > 256 ? 256 : by_samples;
    }
    static constexpr std::size_t bytes_needed(std::size_t light_samples_per_vertex) {
        return (chunk_for(light_samples_per_vertex) + kPadding) *
               (kBytesPerEntry + light_samples_per_vertex * kBytesPerLightSample);
    }

    bool full() const { return count == capacity; }
    void clear() { count = 0, has_smooth = false; }

    // Room for `n` vertices (a chunk: chunk_for()) of `light_samples_per_vertex` samples each.
    void reserve(std::size_t n, std::size_t light_samples_per_vertex) {
        capacity = n;
        stride = padded_entries(n);  // whole vectors: each sample's row stays aligned
        for (auto* a : {&px, &py, &pz, &ex, &ey, &ez, &nx, &ny, &nz, &snx, &sny, &snz, &dx, &dy, &dz, &throughput_r, &throughput_g, &throughput_b,
                        &albedo_r, &albedo_g, &albedo_b, &oren_nayar_a, &oren_nayar_b, &u0, &u1, &roulette})
            a->resize(stride);
        path.resize(stride), flags.resize(stride), random_base.resize(stride);
        for (auto* a : {&light_px, &light_py, &light_pz, &light_ex, &light_ey, &light_ez, &light_nx, &light_ny, &light_nz,
                        &light_r, &light_g, &light_b, &light_pdf_area, &light_u, &light_v, &light_choice})
            a->resize(stride * light_samples_per_vertex);
    }

    // Bytes per entry and per light sample, for WavefrontWorkspace::bytes_needed.
    static constexpr std::size_t kBytesPerEntry = 26 * 4 + 4 + 1 + 8;
    static constexpr std::size_t kBytesPerLightSample = 16 * 4;

    // A vertex; its light samples follow with set_light_sample(count - 1, ...) when it has them.
    // The draws are read only where the path continues past the vertex.
    void push(const SurfacePoint& s, const Material& m, const glm::vec3& d, const glm::vec3& throughput, float bsdf_u,
              float bsdf_v, float roulette_u, uint32_t slot, bool specular_light_elsewhere, bool samples_lights) {
        const std::size_t i = push_vertex(s, m, d, throughput, slot, specular_light_elsewhere, samples_lights);
        u0[i] = bsdf_u, u1[i] = bsdf_v, roulette[i] = roulette_u;
    }
    // A vertex whose random numbers are VertexRandom's of `base` (core/sampling/rng.h), not yet
    // drawn: ShadeKernels::draw_diffuse_random draws them, and its light samples' numbers.
    void push_undrawn(const SurfacePoint& s, const Material& m, const glm::vec3& d, const glm::vec3& throughput,
                      uint64_t base, uint32_t slot, bool specular_light_elsewhere, bool samples_lights) {
        random_base[push_vertex(s, m, d, throughput, slot, specular_light_elsewhere, samples_lights)] = base;
    }

    void set_light_sample(std::size_t entry, uint32_t index, const LightSample& light) {
        const std::size_t k = index * stride + entry;
        light_px[k] = light.position.x, light_py[k] = light.position.y, light_pz[k] = light.position.z;
        light_ex[k] = light.error.x, light_ey[k] = light.error.y, light_ez[k] = light.error.z;
        light_nx[k] = light.normal.x, light_ny[k] = light.normal.y, light_nz[k] = light.normal.z;
        light_r[k] = light.radiance.x, light_g[k] = light.radiance.y, light_b[k] = light.radiance.z;
        light_pdf_area[k] = light.pdf_area;
    }

    // The light points of the undrawn vertices that sample lights, from their numbers once drawn:
    // light_sample_point's, for a sampler that always draws the choice.
    void pick_light_points(const Scene& scene, uint32_t light_samples) {
        for (std::size_t i = 0; i < count; ++i) {
            if (!(flags[i] & kSamplesLights)) continue;
            for (uint32_t j = 0; j < light_samples; ++j) {
                const std::size_t k = j * stride + i;
                set_light_sample(i, j, scene.lights.sample(scene.triangles, light_choice[k], light_u[k], light_v[k]));
            }
        }
    }

private:
    std::size_t push_vertex(const SurfacePoint& s, const Material& m, const glm::vec3& d, const glm::vec3& throughput,
                            uint32_t slot, bool specular_light_elsewhere, bool samples_lights) {
        const std::size_t i = count++;
        px[i] = s.position.x, py[i] = s.position.y, pz[i] = s.position.z;
        ex[i] = s.error.x, ey[i] = s.error.y, ez[i] = s.error.z;
        nx[i] = s.normal.x, ny[i] = s.normal.y, nz[i] = s.normal.z;
        if (s.smooth) {
            snx[i] = s.shading_normal.x, sny[i] = s.shading_normal.y, snz[i] = s.shading_normal.z;
            has_smooth = true;
        }
        dx[i] = d.x, dy[i] = d.y, dz[i] = d.z;
        throughput_r[i] = throughput.x, throughput_g[i] = throughput.y, throughput_b[i] = throughput.z;
        albedo_r[i] = m.albedo.x, albedo_g[i] = m.albedo.y, albedo_b[i] = m.albedo.z;
        const bool oren_nayar = m.type == MaterialType::oren_nayar;
        const OrenNayarTerms terms = oren_nayar ? oren_nayar_terms(m.sigma) : OrenNayarTerms{1.0f, 0.0f};
        oren_nayar_a[i] = terms.a, oren_nayar_b[i] = terms.b;
        path[i] = slot;
        flags[i] = uint8_t((oren_nayar ? kOrenNayar : 0) | (specular_light_elsewhere ? kSpecularLightElsewhere : 0) |
                           (samples_lights ? kSamplesLights : 0) | (s.smooth ? kSmooth : 0));
        return i;
    }
};

}  // namespace wt
