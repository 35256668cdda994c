#pragma once
// The wavefront stages. Each is a loop over a queue; the driver (wavefront_renderer.cpp) runs
// them in order for one batch of one tile on one worker, so the queues stay in that core's L2.

#include "core/film/film.h"
#include "core/scene/scene.h"
#include "kernels/isa/intersect_kernels.h"
#include "kernels/isa/shade_kernels.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/work/render_stats.h"
#include "kernels/work/tiles.h"

namespace wt {

class PhotonMaps;

// The generate and shade stages run the scene's estimator (core/path/estimator.h), chosen once per
// call, for the whole queue.

// Camera rays for samples [sample_begin, sample_end) of every pixel in the tile, sample-major,
// so each pixel's samples sit in the path table in ascending order.
void generate_camera_rays(const Scene& scene, const Tile& tile, uint32_t sample_begin, uint32_t sample_end,
                          PathTable& paths, RayQueue& rays);
// The same for some of a tile's pixels only (adaptive sampling's pixels still sampled).
void generate_camera_rays(const Scene& scene, TilePixels pixels, uint32_t sample_begin, uint32_t sample_end,
                          PathTable& paths, RayQueue& rays);

// What the intersect and shadow stages trace against, and with which kernels: the BVH when
// the render has one, else the flat primitive lists.
struct IntersectContext {
    SceneView scene;
    const IntersectKernels* kernels;
    const BvhView* bvh = nullptr;
};

// Closest hit of every ray in the queue. `coherent`: the rays are camera rays, neighbours in
// the queue are neighbours in the image.
void intersect_closest_stage(const IntersectContext& context, const RayQueue& rays, HitQueue& hits, bool coherent);

// Emission, light samples into `shadows`, and surviving continuations into `next_rays`; with
// AOVs (a non-empty `paths.first_surface`), each path's first surface (core/path/first_surface.h);
// with `photons` (the batch's maps, when the scene merges photons), their estimate where a path
// gathers it (gathers_photons).
// `kernels` compute the surface points and shade the diffuse vertices, a chunk at a time in
// `chunks` (shade_queue.h).
void shade_stage(const Scene& scene, const ShadeKernels& kernels, uint32_t bounce, const RayQueue& rays, const HitQueue& hits,
                 PathTable& paths, ShadeChunks& chunks, RayQueue& next_rays, ShadowQueue& shadows,
                 const PhotonMaps* photons);

// Any-hit test of every shadow ray; unblocked ones add their contribution to their path.
void shadow_stage(const IntersectContext& context, ShadowQueue& shadows, PathTable& paths);

}  // namespace wt
