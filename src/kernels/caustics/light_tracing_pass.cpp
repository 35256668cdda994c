#include "kernels/caustics/light_tracing_pass.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/base/aligned_vector.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/isa/shade_kernels.h"
#include "kernels/queues/kernel_padding.h"
#include "kernels/queues/light_point_queue.h"
#include "kernels/queues/surface_chunk.h"

namespace wt {

// One worker's queues for the wavefront light paths: per path of an item its key and power, its
// rays as a RayQueue (the throughput is the bounces' weight), and the camera connections as a
// ShadowQueue whose `path` is the pixel the splat lands in.
struct LightPathWorkspace {
    AlignedVector<uint64_t> key;
    AlignedVector<float> power_r, power_g, power_b;
    RayQueue rays, next_rays;
    HitQueue hits;
    ShadowQueue connections;  // the camera connections; before the first bounce, the first rays
    // The shade kernels' queues hold a chunk of entries at a time (as the camera paths' diffuse
    // vertices, kernels/queues/diffuse_vertex_queue.h): read back while in the core's cache.
    static constexpr std::size_t kChunk = 256;
    LightPointQueue points;   // the starts at area lights, for the shade kernels
    SurfaceChunk surfaces;    // the surface points of a chunk of the rays' hits, by the shade kernels
    SpecularVertexQueue specular;  // flat mirror and glass vertices of a bounce, for the shade kernels
    std::vector<std::pair<uint32_t, Photon>> photons;  // by vertex, then slot: sorted to the paths' order
    std::vector<uint32_t> photon_starts;               // the sort's: where each slot's photons go

    explicit LightPathWorkspace(std::size_t paths) {
        key.resize(paths), power_r.resize(paths), power_g.resize(paths), power_b.resize(paths);
        rays.reserve(paths), next_rays.reserve(paths), hits.reserve(paths), connections.reserve(paths);
        points.reserve(kChunk), specular.reserve(kChunk);
    }
    // Per path its key, power, two ray queues' entries, a hit, a connection and the photon sort's
    // start; then the kernels' chunks.
    static constexpr std::size_t bytes_needed(std::size_t paths) {
        return paths * (8 + 12 + 2 * 45 + 16 + 45 + 4) + padded_entries(kChunk) * LightPointQueue::kBytesPerEntry +
               padded_entries(kChunk) * SpecularVertexQueue::kBytesPerEntry + SurfaceChunk::kBytes;
    }
    LightRay light_ray(std::size_t i) const {
        const uint32_t slot = rays.path[i];
        return {rays.ray(i), {power_r[slot], power_g[slot], power_b[slot]}, rays.throughput(i)};
    }
};

std::size_t LightTracingPass::bytes_per_worker() {
    return kBufferedSplats * sizeof(CameraSplat) + LightPathWorkspace::bytes_needed(kPathsPerItem);
}

LightTracingPass::LightTracingPass(const Scene& scene, const BvhView* bvh, int threads)
    : scene_(scene), tracer_(scene, bvh, scene.merges_photons), paths_per_sample_(light_paths_per_sample(scene.settings)),
      buffers_(std::size_t(threads)), workspaces_(std::size_t(threads)) {}

LightTracingPass::~LightTracingPass() = default;

void LightTracingPass::flush(Film& film, std::vector<CameraSplat>& buffer, RayCounts& counts) {
    {
        const std::lock_guard<std::mutex> lock(film_mutex_);
        for (const CameraSplat& s : buffer)
            if (!film.add_splat(s.pixel, s.value)) ++counts.dropped_splats;
    }
    buffer.clear();
}

// The paths [first, end) of one sample, advanced together vertex by vertex: the same vertex code
// in the same order per path as LightPathTracer::trace, so the same splats.
void LightTracingPass::trace_item_wavefront(const IntersectContext& context, const ShadeKernels& shade, uint32_t sample,
                                            uint64_t first, uint64_t end, LightPathWorkspace& ws,
                                            std::vector<CameraSplat>& splats, PhotonList* photons,
                                            RayCounts& counts) const {
    ws.rays.count = 0;
    ws.photons.clear();
    // Every started path's first ray, in path order, in ws.connections: where it misses every
    // specular target (LightPathTracer::first_ray_counts, asked of the batch through the any-hit
    // kernels) its first hit would end it, so it is not traced.
    ws.connections.count = 0;
    if (tracer_.starts_at_area_lights_only() && shade.width > 1) {
        // The points and powers here, the rays by the shade kernels (area_light_rays.h), a chunk
        // at a time.
        ws.points.count = 0;
        for (uint64_t index = first; index < end; ++index) {
            const uint32_t slot = uint32_t(index - first);
            ws.key[slot] = light_path_key(scene_.settings.seed, index, sample);
            const AreaLightStart s = tracer_.area_light_start(ws.key[slot]);
            ws.power_r[slot] = s.power.x, ws.power_g[slot] = s.power.y, ws.power_b[slot] = s.power.z;
            ws.points.push(s.light.position, s.light.error, s.light.normal, s.direction.first, s.direction.second, slot);
            if (ws.points.count == LightPathWorkspace::kChunk || index + 1 == end) {
                shade.aim_area_light_rays(ws.points, ws.connections);
                ws.points.count = 0;
            }
        }
    } else {
        // Which start the paths take, decided once for the batch (LightPathTracer::start).
        const auto start_all = [&](auto&& start) {
            for (uint64_t index = first; index < end; ++index) {
                const uint32_t slot = uint32_t(index - first);
                ws.key[slot] = light_path_key(scene_.settings.seed, index, sample);
                const auto r = start(ws.key[slot]);
                if (!r) continue;
                ws.power_r[slot] = r->power.x, ws.power_g[slot] = r->power.y, ws.power_b[slot] = r->power.z;
                ws.connections.push(ShadowRay{r->ray, std::numeric_limits<float>::infinity(), r->weight}, slot);
            }
        };
        if (tracer_.starts_at_area_lights_only())
            start_all([&](uint64_t key) { return tracer_.start(key); });
        else
            start_all([&](uint64_t key) { return tracer_.start_at_listed_lights(key); });
    }
    const SpecularTargets* targets = tracer_.specular_targets();
    if (targets && ws.connections.count > 0)
        context.kernels->any_raypacket(targets->view(), ray_view(ws.connections), ws.connections.occluded.data());
    for (std::size_t i = 0; i < ws.connections.count; ++i)
        if (!targets || ws.connections.occluded[i])
            ws.rays.push(ws.connections.ray(i), ws.connections.contribution(i), ws.connections.path[i], 0);
    counts.light_paths += end - first;
    const bool surface_kernel = shade.width > 1;
    const uint32_t surface_kernel_ids_end = surface_kernel_ids(scene_);
    for (uint32_t vertex = 1; ws.rays.count > 0; ++vertex) {
        counts.light_rays += ws.rays.count;
        intersect_closest_stage(context, ws.rays, ws.hits, false);
        ws.next_rays.count = 0;
        ws.connections.count = 0;
        ws.specular.count = 0;
        const auto continue_specular = [&] {
            shade.continue_specular(ws.specular, tracer_.roulette_at(vertex), scene_.settings.accuracy.fresnel, ws.next_rays);
            ws.specular.count = 0;
        };
        std::optional<Material> textured;  // at_vertex's scratch
        for (std::size_t i = 0; i < ws.rays.count; ++i) {
            // The surface points a chunk at a time by the shade kernels, as the camera paths' (shade_queue.h).
            const std::size_t in_chunk = i % SurfaceChunk::kSize;
            if (surface_kernel && in_chunk == 0)
                shade.surface_points(scene_, ws.rays, ws.hits, i, std::min(SurfaceChunk::kSize, ws.rays.count - i), ws.surfaces);
            const Hit hit = ws.hits.hit(i);
            if (!hit.found()) continue;
            const uint32_t slot = ws.rays.path[i];
            const LightRay at = ws.light_ray(i);
            LightVertex v;
            if (surface_kernel && hit.prim < surface_kernel_ids_end) {
                const SurfacePoint surface = ws.surfaces.at(in_chunk);
                // Flat mirrors and glass go to the shade kernels' queue, continued by the chunk.
                if (tracer_.queue_specular(ws.key[slot], vertex, at, surface, slot, ws.specular)) {
                    if (ws.specular.full()) continue_specular();
                    continue;
                }
                v = tracer_.at_vertex(ws.key[slot], vertex, at, hit, surface, textured);
            } else {
                v = tracer_.at_vertex(ws.key[slot], vertex, at, hit, textured);
            }
            if (v.connection)
                ws.connections.push(ShadowRay{v.connection->ray, v.connection->tmax, v.connection->splat.value},
                                    v.connection->splat.pixel);
            if (photons && v.photon) ws.photons.emplace_back(slot, *v.photon);
            if (v.next) ws.next_rays.push(v.next->ray, v.next->weight, slot, 0);
        }
        // (The next rays' order within a bounce changes no bit: each path's photons are sorted
        // back into vertex order below, and the film's sums are exact.)
        if (ws.specular.count > 0) continue_specular();
        counts.camera_connections += ws.connections.count;
        if (ws.connections.count > 0) {
            if (context.bvh)
                context.kernels->any_bvh(*context.bvh, ray_view(ws.connections), ws.connections.occluded.data());
            else
                context.kernels->any_raypacket(context.scene, ray_view(ws.connections), ws.connections.occluded.data());
            for (std::size_t i = 0; i < ws.connections.count; ++i)
                if (!ws.connections.occluded[i]) splats.push_back({ws.connections.path[i], ws.connections.contribution(i)});
        }
        std::swap(ws.rays, ws.next_rays);
    }
    if (!photons) return;
    counts.photons += ws.photons.size();
    // Collected vertex by vertex; a counting sort on the slot (stable: each path's keep their
    // vertex order) places them path by path, what trace() gives.
    ws.photon_starts.assign(std::size_t(end - first) + 1, 0);
    for (const auto& p : ws.photons) ++ws.photon_starts[p.first + 1];
    for (std::size_t slot = 0; slot + 1 < ws.photon_starts.size(); ++slot) ws.photon_starts[slot + 1] += ws.photon_starts[slot];
    const std::size_t base = photons->size();
    photons->resize(base + ws.photons.size());
    for (const auto& p : ws.photons) (*photons)[base + ws.photon_starts[p.first]++] = p.second;
}

void LightTracingPass::render(Film& film, uint32_t sample_begin, uint32_t sample_end, ThreadPool& pool,
                              std::vector<RayCounts>& counts, const IntersectContext* wavefront, PhotonMaps* photons) {
    if (!film.has_splats()) throw std::invalid_argument("render: light tracing needs a film with splat channels");
    if (sample_end <= sample_begin) return;
    const uint64_t items_per_sample = (paths_per_sample_ + kPathsPerItem - 1) / kPathsPerItem;
    const uint64_t items = items_per_sample * (sample_end - sample_begin);
    if (photons) photons->start_batch(sample_begin, sample_end, items_per_sample);
    const ShadeKernels* shade = wavefront ? &shade_kernels(wavefront->kernels->isa) : nullptr;
    pool.parallel_for(std::size_t(items), [&](std::size_t item, int worker) {
        const uint32_t sample = sample_begin + uint32_t(item / items_per_sample);
        const uint64_t first = (item % items_per_sample) * kPathsPerItem;
        const uint64_t end = std::min(paths_per_sample_, first + kPathsPerItem);
        RayCounts& c = counts[std::size_t(worker)];
        std::vector<CameraSplat>& buffer = buffers_[std::size_t(worker)];
        PhotonList* item_photons = photons ? &photons->photons(item) : nullptr;
        if (wavefront) {
            auto& ws = workspaces_[std::size_t(worker)];
            if (!ws) ws = std::make_unique<LightPathWorkspace>(std::size_t(kPathsPerItem));
            trace_item_wavefront(*wavefront, *shade, sample, first, end, *ws, buffer, item_photons, c);
        } else {
            for (uint64_t path = first; path < end; ++path) tracer_.trace(path, sample, c, buffer, nullptr, item_photons);
        }
        if (buffer.size() >= kBufferedSplats) flush(film, buffer, c);
    });
    for (std::size_t w = 0; w < buffers_.size(); ++w) flush(film, buffers_[w], counts[w]);
    film.add_splat_samples(sample_end - sample_begin);
}

}  // namespace wt
