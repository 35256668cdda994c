#pragma once
// The scalar reference integrator: one camera path at a time, start to finish, in the plainest
// form of the estimator. It is the oracle the wavefront renderer is tested against and the
// baseline its speed is measured against; keep it small and obviously right.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/film/aov.h"
#include "core/film/film.h"
#include "core/path/first_surface.h"
#include "core/scene/scene.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/work/render_stats.h"
#include "kernels/work/tiles.h"

namespace wt {

class PhotonMaps;

// One line per path vertex, for replaying a single sample (wavetrace render --debug-sample).
struct PathVertexRecord {
    uint32_t bounce;
    Hit hit;
    glm::vec3 position, normal, shading_normal;  // the shading normal equals `normal` when flat
    uint32_t material;
    glm::vec3 throughput;        // arriving at this vertex
    glm::vec3 emission_added;
    uint32_t shadow_rays_traced, shadow_rays_unoccluded;
    glm::vec3 direct_added;
    // Where the path gathers photons (photon_radius > 0): the lookup's radius, the photons it
    // counted and the radiance they added.
    float photon_radius;
    uint32_t photons_gathered;
    glm::vec3 photons_added;
};

// Radiance of sample `sample` of pixel `pixel`, times the pixel filter's sample weight (what the
// film receives; the weight is 1 but for a filter with negative lobes, and the vertices' records
// are unweighted). If `record` is given, each vertex is appended.
// Rays are traced through `bvh` when given (the scalar kernels: the same hits as the flat
// loops, found in logarithmic time), else against every primitive. If `first_surface` is
// given (default-constructed), the path's AOV data is recorded in it. `photons`: when the scene
// merges photons, the maps of a batch holding `sample` (without them the path gathers none).
glm::vec3 trace_reference_path(const Scene& scene, uint32_t pixel, uint32_t sample, RayCounts& counts,
                               std::vector<PathVertexRecord>* record = nullptr, const BvhView* bvh = nullptr,
                               FirstSurface* first_surface = nullptr, const PhotonMaps* photons = nullptr);

// Samples [sample_begin, sample_end) of every pixel of the tile, with the AOVs the film has channels for.
void render_reference_tile(const Scene& scene, const Tile& tile, uint32_t sample_begin, uint32_t sample_end, Film& film,
                           RayCounts& counts, const BvhView* bvh = nullptr, const AovSelection& aovs = {},
                           const PhotonMaps* photons = nullptr);
// The same for some of a tile's pixels: adaptive sampling's pixels still sampled.
void render_reference_pixels(const Scene& scene, TilePixels pixels, uint32_t sample_begin, uint32_t sample_end,
                             Film& film, RayCounts& counts, const BvhView* bvh = nullptr, const AovSelection& aovs = {},
                             const PhotonMaps* photons = nullptr);

}  // namespace wt
