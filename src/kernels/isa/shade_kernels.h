#pragma once
// The SIMD shade kernels, compiled once per instruction set (shade_<isa>.cpp) and picked at run
// time with the intersection kernels' ISA. Only plain declarations here: this header is included
// by the per-ISA translation units.

#include <cstddef>
#include <cstdint>

#include "kernels/isa/intersect_kernels.h"

namespace wt {

struct DiffuseContinuation;
struct HitQueue;
struct Scene;
struct SurfaceChunk;
struct DiffuseLightSampling;
struct DiffuseVertexQueue;
class LightTable;
struct LightPointQueue;
struct SpecularVertexQueue;
enum class FresnelModel : uint8_t;
struct RayQueue;
struct ShadowQueue;

struct ShadeKernels {
    Isa isa;
    int width;
    // surface_at for hits [first, first + count) of the queue (count at most SurfaceChunk::kSize),
    // into the chunk from its start, for the hits on the scene's own triangles and spheres
    // (surface_kernel_ids, kernels/shading/surface_points.h).
    void (*surface_points)(const Scene&, const RayQueue&, const HitQueue&, std::size_t first, std::size_t count, SurfaceChunk&);
    // continue_path for every vertex of the queue, in its order; the paths that go on are appended
    // to `next` (kernels/shading/diffuse_continuation.h).
    void (*continue_diffuse)(const DiffuseVertexQueue&, const DiffuseContinuation&, RayQueue& next);
    // The random numbers of every vertex of the queue, pushed undrawn (push_undrawn), and of its
    // first `light_samples` light samples (kernels/shading/diffuse_random.h).
    void (*draw_diffuse_random)(DiffuseVertexQueue&, uint32_t light_samples);
    // The light points of every vertex of the queue from those numbers, for a table with
    // LightTable::few_untextured_emitters (kernels/shading/light_points.h).
    void (*pick_light_points)(DiffuseVertexQueue&, const LightTable&, uint32_t light_samples);
    // The light samples of every vertex of the queue that has them, each vertex's in index order;
    // those that can contribute are appended to `shadows` (kernels/shading/diffuse_light_samples.h).
    void (*sample_diffuse_lights)(const DiffuseVertexQueue&, const DiffuseLightSampling&, ShadowQueue& shadows);
    // The first rays of light paths from their points on area lights, in the queue's order, those
    // above the light appended to `rays` (kernels/shading/area_light_rays.h).
    void (*aim_area_light_rays)(const LightPointQueue&, ShadowQueue& rays);
    // The flat mirror and glass vertices of one bounce of light or camera paths, the paths that
    // go on appended to `next` in the queue's order; `roulette` at this bounce
    // (kernels/shading/specular_continuation.h).
    void (*continue_specular)(const SpecularVertexQueue&, bool roulette, FresnelModel fresnel, RayQueue& next);
};

// Defined in shade_<isa>.cpp, each compiled with its own target flags.
extern const ShadeKernels kShadeScalar;
extern const ShadeKernels kShadeSse4;
extern const ShadeKernels kShadeAvx2;
extern const ShadeKernels kShadeAvx512;

// Throws std::runtime_error naming the ISA if this CPU cannot run it.
const ShadeKernels& shade_kernels(Isa isa);

}  // namespace wt
