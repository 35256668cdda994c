#pragma once
// The SoA queues the wavefront stages read and write. One set per worker, sized once for a
// batch and reused for every tile, so the hot loop never allocates. All rays in a queue are
// at the same bounce: a batch starts all its paths together and advances them in lockstep.

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/base/aligned_vector.h"
#include "core/path/first_surface.h"
#include "core/path/path_vertex.h"
#include "core/base/ray.h"
#include "kernels/queues/diffuse_vertex_queue.h"
#include "kernels/queues/specular_vertex_queue.h"
#include "kernels/queues/surface_chunk.h"

namespace wt {

// One slot per camera path of the batch: where its sample goes and what it has gathered.
struct PathTable {
    AlignedVector<uint32_t> pixel, sample;
    AlignedVector<uint64_t> key;  // random-number key, from (seed, pixel, sample)
    AlignedVector<float> radiance_r, radiance_g, radiance_b;
    AlignedVector<float> filter_weight;  // CameraRay::weight: multiplies the radiance on the film
    // The albedo, normal and depth AOVs' data per path; empty (and never touched) without them.
    AlignedVector<FirstSurface> first_surface;
    // A scene with an emitter selection (Scene::emitter_selection) only, else empty: the
    // geometric normal of the vertex that cast the path's ray, which the light tree weighs the
    // emitter the ray hits for (emission_added), as that vertex's light samples were picked.
    AlignedVector<float> nx, ny, nz;

    void resize(std::size_t n, bool with_aovs, bool with_normals = false) {
        pixel.resize(n), sample.resize(n), key.resize(n);
        radiance_r.resize(n), radiance_g.resize(n), radiance_b.resize(n), filter_weight.resize(n);
        first_surface.resize(with_aovs ? n : 0);
        for (auto* a : {&nx, &ny, &nz}) a->resize(with_normals ? n : 0);
    }
    void set_normal(uint32_t slot, const glm::vec3& n) { nx[slot] = n.x, ny[slot] = n.y, nz[slot] = n.z; }
    glm::vec3 normal(uint32_t slot) const { return {nx[slot], ny[slot], nz[slot]}; }
    void add_radiance(uint32_t slot, const glm::vec3& c) {
        radiance_r[slot] += c.x, radiance_g[slot] += c.y, radiance_b[slot] += c.z;
    }
    glm::vec3 radiance(uint32_t slot) const { return {radiance_r[slot], radiance_g[slot], radiance_b[slot]}; }
    // What the film receives: the radiance times the filter's weight, as trace_path returns it.
    glm::vec3 weighted_radiance(uint32_t slot) const { return radiance(slot) * filter_weight[slot]; }
};

// Rays still alive and what the next hit needs to know about the path that cast them.
struct RayQueue {
    AlignedVector<float> ox, oy, oz, dx, dy, dz;
    AlignedVector<float> throughput_r, throughput_g, throughput_b;
    AlignedVector<uint32_t> path;          // slot in the PathTable
    // Bit flags: kCountEmission (PathContinuation::count_emission; camera rays too) and
    // kSpecularLightElsewhere (PathContinuation::specular_light_elsewhere).
    AlignedVector<uint8_t> count_emission;
    // kRoughPdf: bsdf_pdf holds a rough bounce's pdf (set without mis; with mis it always does).
    // kCountEnvironment: PathContinuation::count_environment, set only in a scene with a
    // "lights" list (shade_queue.h), where camera rays count what they escape to anyway.
    static constexpr uint8_t kCountEmission = 1, kSpecularLightElsewhere = 2, kRoughPdf = 4, kCountEnvironment = 8;
    AlignedVector<float> bsdf_pdf;         // mis, or kRoughPdf: PathContinuation::bsdf_pdf
    std::size_t count = 0;

    void reserve(std::size_t n) {
        for (auto* a : {&ox, &oy, &oz, &dx, &dy, &dz, &throughput_r, &throughput_g, &throughput_b, &bsdf_pdf}) a->resize(n);
        path.resize(n), count_emission.resize(n);
    }
    void push(const Ray& r, const glm::vec3& throughput, uint32_t slot, uint8_t emission) {
        const std::size_t i = count++;
        ox[i] = r.origin.x, oy[i] = r.origin.y, oz[i] = r.origin.z;
        dx[i] = r.direction.x, dy[i] = r.direction.y, dz[i] = r.direction.z;
        throughput_r[i] = throughput.x, throughput_g[i] = throughput.y, throughput_b[i] = throughput.z;
        path[i] = slot;
        count_emission[i] = emission;
    }
    // A continuation; the pdf is written only where the estimator reads it (mis).
    template <bool kWithPdf>
    void push(const PathContinuation& next, uint32_t slot) {
        uint8_t rough_pdf = 0;
        if constexpr (kWithPdf) {
            bsdf_pdf[count] = next.bsdf_pdf;
        } else if (next.bsdf_pdf > 0.0f) {
            bsdf_pdf[count] = next.bsdf_pdf;
            rough_pdf = kRoughPdf;
        }
        push(next.ray, next.throughput, slot,
             uint8_t((next.count_emission ? kCountEmission : 0) | (next.specular_light_elsewhere ? kSpecularLightElsewhere : 0) |
                     rough_pdf));
    }
    Ray ray(std::size_t i) const { return {{ox[i], oy[i], oz[i]}, {dx[i], dy[i], dz[i]}}; }
    glm::vec3 throughput(std::size_t i) const { return {throughput_r[i], throughput_g[i], throughput_b[i]}; }
};

// Closest hits of a RayQueue, index for index.
struct HitQueue {
    AlignedVector<float> t, u, v;
    AlignedVector<uint32_t> prim;

    void reserve(std::size_t n) { t.resize(n), u.resize(n), v.resize(n), prim.resize(n); }
    void set(std::size_t i, const Hit& h) { t[i] = h.t, u[i] = h.u, v[i] = h.v, prim[i] = h.prim; }
    Hit hit(std::size_t i) const { return {t[i], prim[i], u[i], v[i]}; }
};

// Shadow rays of one bounce, each carrying the radiance it adds to its path if unblocked.
struct ShadowQueue {
    AlignedVector<float> ox, oy, oz, dx, dy, dz, tmax;
    AlignedVector<float> contribution_r, contribution_g, contribution_b;
    AlignedVector<uint32_t> path;
    AlignedVector<uint8_t> occluded;  // written by the any-hit kernel
    std::size_t count = 0;

    void reserve(std::size_t n) {
        for (auto* a : {&ox, &oy, &oz, &dx, &dy, &dz, &tmax, &contribution_r, &contribution_g, &contribution_b}) a->resize(n);
        path.resize(n), occluded.resize(n);
    }
    void push(const ShadowRay& s, uint32_t slot) {
        const std::size_t i = count++;
        ox[i] = s.ray.origin.x, oy[i] = s.ray.origin.y, oz[i] = s.ray.origin.z;
        dx[i] = s.ray.direction.x, dy[i] = s.ray.direction.y, dz[i] = s.ray.direction.z;
        tmax[i] = s.tmax;
        contribution_r[i] = s.contribution.x, contribution_g[i] = s.contribution.y, contribution_b[i] = s.contribution.z;
        path[i] = slot;
    }
    Ray ray(std::size_t i) const { return {{ox[i], oy[i], oz[i]}, {dx[i], dy[i], dz[i]}}; }
    glm::vec3 contribution(std::size_t i) const { return {contribution_r[i], contribution_g[i], contribution_b[i]}; }
};

// What the shade stage's kernels (kernels/shading) read and write besides the queues: a chunk
// of surface points, one of diffuse vertices and one of mirror and glass vertices
// (kernels/wavefront/shade_queue.h).
struct ShadeChunks {
    static constexpr std::size_t kSpecularChunk = 256;
    SurfaceChunk surfaces;
    DiffuseVertexQueue diffuse;
    SpecularVertexQueue specular;
};

// Everything one worker needs to run a batch; allocated once per worker.
struct WavefrontWorkspace {
    PathTable paths;
    RayQueue rays, next_rays;
    HitQueue hits;
    ShadowQueue shadows;
    ShadeChunks shade;

    // What the constructor allocates, per path: the path table (2 x 4 + 8 + 4 x 4 bytes, the
    // first surface with AOVs, 3 x 4 with the normals), two ray queues (10 x 4 + 4 + 1), the
    // hits (3 x 4 + 4); per shadow ray (10 x 4 + 4 + 1); and the shade stage's chunks.
    static constexpr std::size_t bytes_needed(std::size_t batch_paths, std::size_t shadow_rays_per_hit, bool with_aovs,
                                              bool with_normals = false) {
        const std::size_t path_table = 32 + (with_aovs ? sizeof(FirstSurface) : 0) + (with_normals ? 12 : 0);
        return batch_paths * (path_table + 2 * 45 + 16) + batch_paths * shadow_rays_per_hit * 45 +
               DiffuseVertexQueue::bytes_needed(shadow_rays_per_hit) + SurfaceChunk::kBytes +
               padded_entries(ShadeChunks::kSpecularChunk) * SpecularVertexQueue::kBytesPerEntry;
    }

    // `with_normals`: the scene has an emitter selection (PathTable::nx).
    WavefrontWorkspace(std::size_t batch_paths, std::size_t shadow_rays_per_hit, bool with_aovs, bool with_normals = false) {
        paths.resize(batch_paths, with_aovs, with_normals);
        rays.reserve(batch_paths);
        next_rays.reserve(batch_paths);
        hits.reserve(batch_paths);
        shadows.reserve(batch_paths * shadow_rays_per_hit);
        shade.diffuse.reserve(DiffuseVertexQueue::chunk_for(shadow_rays_per_hit), shadow_rays_per_hit);
        shade.specular.reserve(ShadeChunks::kSpecularChunk);
    }
};

}  // namespace wt
