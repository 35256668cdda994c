#pragma once
// What a render will allocate, estimated before anything is: the film, each worker's wavefront
// queues, the BVH (with its build's temporaries) and the scene's geometry, held against the
// memory the machine has available. A render that cannot fit is refused with the estimate and
// the option to change, instead of dying of std::bad_alloc (or the OOM killer) minutes in.

#include <cstddef>
#include <string>

#include "core/system/available_memory.h"
#include "core/scene/scene.h"
#include "kernels/render_options.h"

namespace wt {

// Camera paths one worker's queues must hold: a batch is samples_per_batch() samples of every
// pixel of a tile (wavefront_renderer.h), the most any tile of the image takes, so never more
// than a tile's pixels times spp, however large --batch-paths is.
std::size_t workspace_paths(int width, int height, int spp, int tile_size, std::size_t batch_paths);

struct MemoryEstimate {
    double film = 0.0;              // Film::bytes_needed
    double queues_per_worker = 0.0; // WavefrontWorkspace::bytes_needed, 0 for the reference integrator
    int workers = 1;
    double bvh = 0.0;               // nodes, leaf blocks and the build's temporaries at their peak
    double geometry = 0.0;          // the scene's primitive arrays (already allocated when this is asked)
    double photons = 0.0;           // one batch of photon maps at its peak (kernels/caustics/photon_memory.h), expected
    double instances = 0.0;         // placements, their records and the top-level tree (part allocated)
    std::size_t instance_count = 0;
    double textures = 0.0;          // the textures' mip pyramids and coordinates (allocated, as geometry)
    double lights = 0.0;            // the emitters' table, their selection by power or tree, the listed lights (allocated)

    double queues() const { return queues_per_worker * double(workers); }
    // What the render has yet to allocate.
    double to_allocate() const { return film + queues() + bvh + photons + instances; }
    double total() const { return to_allocate() + geometry + textures + lights; }
};

// What one instance costs, whatever its mesh: its placement, its traversal record and its share
// of the top-level tree and of that tree's build.
double bytes_per_instance(int node_width);

// For the options' threads (0: one per hardware thread), integrator, kernels and accel.
MemoryEstimate estimate_render_memory(const Scene& scene, const RenderOptions& options);


// "needs 11.3 GB (film 2.6 MB, 2 workers x 5.6 GB of wavefront queues, BVH 0 B, geometry 2.0 kB),
// more than the 20.1 GB available; lower --shadow-rays or --tile-size, or use fewer --threads"
// Empty when it fits (or nothing is known of the memory available).
std::string memory_problem(const MemoryEstimate& estimate, double available);

// "textures: 3 images, 5.6 MB (mip levels of linear RGBA floats, and their coordinates)"
std::string texture_memory_line(const Scene& scene);

// "996019 triangles: 87.6 MB of primitive arrays (88 B each), 18.0 MB of vertex normals (18.1 B a
// triangle)": the scene's own triangles and its instanced meshes', each mesh once.
std::string geometry_memory_line(const Scene& scene);

// "12.3 MB" and the like, for messages.
std::string format_bytes(double bytes);

}  // namespace wt
