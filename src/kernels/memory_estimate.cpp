#include "kernels/memory_estimate.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "kernels/accel/bvh_view.h"
#include "kernels/accel/sah_builder.h"
#include "kernels/caustics/light_tracing_pass.h"
#include "kernels/caustics/photon_memory.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/renderer.h"
#include "kernels/wavefront/wavefront_renderer.h"

namespace wt {

std::size_t workspace_paths(int width, int height, int spp, int tile_size, std::size_t batch_paths) {
    // The last column and row of tiles are narrower, and a smaller tile takes more samples per
    // batch: ask every tile shape the image has.
    const int widths[2] = {std::min(width, tile_size), width % tile_size};
    const int heights[2] = {std::min(height, tile_size), height % tile_size};
    std::size_t most = 0;
    for (const int w : widths)
        for (const int h : heights)
            if (w > 0 && h > 0) {
                const Tile tile{0, 0, w, h};
                most = std::max(most, std::size_t(tile.pixel_count()) * samples_per_batch(tile, batch_paths, spp));
            }
    return most;
}

namespace {

// Per primitive, the larger of the build's two phases (bvh_build.cpp), with the wide nodes,
// which the collapse reserves at one per four primitives, and each primitive's scene id in
// both: first a PrimRef and at most two binary nodes, then its leaf block (rows floats).
double bvh_bytes(const Scene& scene, const RenderOptions& options) {
    double primitives = double(scene.primitive_count());
    for (const InstancedMesh& m : scene.instances.meshes) primitives += double(m.triangles.size());  // each mesh once
    const double rows = scene.settings.accuracy.triangles == TriangleTest::watertight ? kWatertightRows : kMollerTrumboreRows;
    const double node = options.bvh.node_width == 4 ? sizeof(BvhNode<4>) : sizeof(BvhNode<8>);
    const double tree = sizeof(PrimRef) + 2.0 * sizeof(BinaryNode), leaves = rows * sizeof(float);
    return primitives * (std::max(tree, leaves) + sizeof(uint32_t) + node / 4.0);
}

// The triangles' and spheres' arrays (SphereSoA: 4 floats and a material index each); an
// instanced mesh's triangles once, however many instances place it; the vertex normals.
double geometry_bytes(const Scene& scene) {
    double bytes = double(scene.triangles.bytes() + scene.shading_normals.bytes());
    for (const InstancedMesh& m : scene.instances.meshes) bytes += double(m.triangles.bytes() + m.shading_normals.bytes());
    return bytes + double(scene.spheres.size()) * (4 * sizeof(float) + sizeof(uint32_t));
}

// The textures' mip pyramids and the coordinates they are looked up at: 0 without textures.
double texture_bytes(const Scene& scene) {
    double bytes = double(scene.texture_coordinates.bytes());
    for (const InstancedMesh& m : scene.instances.meshes) bytes += double(m.texture_coordinates.bytes());  // each mesh once
    for (const MipPyramid& t : scene.textures) bytes += double(t.bytes());
    return bytes;
}

}  // namespace

double bytes_per_instance(int node_width) {
    // Its placement in the scene and in the traversal's records, and the top level's build: a
    // PrimRef, two binary nodes, and one wide node per W - 1 instances (one instance per leaf).
    const double node = node_width == 4 ? sizeof(BvhNode<4>) : sizeof(BvhNode<8>);
    return double(sizeof(Instance) + sizeof(InstanceRecord) + sizeof(PrimRef) + 2 * sizeof(BinaryNode)) +
           node / double(node_width - 1);
}

MemoryEstimate estimate_render_memory(const Scene& scene, const RenderOptions& options) {
    MemoryEstimate e;
    const RenderSettings& s = scene.settings;
    e.film = Film::bytes_needed(s.width, s.height, render_film_channels(scene, options.aovs).size());
    // Adaptive sampling: each pixel's stop (adaptive_state.h) and the rule's flag (stopping_rule.cpp).
    if (s.adaptive.enabled()) e.film += double(s.width) * double(s.height) * (sizeof(uint32_t) + 1);
    e.workers = options.threads > 0 ? options.threads : default_thread_count();
    if (options.integrator == Integrator::wavefront)
        e.queues_per_worker = double(WavefrontWorkspace::bytes_needed(
            workspace_paths(s.width, s.height, s.spp, options.tile_size, options.batch_paths), std::size_t(s.shadow_rays),
            options.aovs.needs_path_data(), !scene.emitter_selection.empty()));
    if (scene.light_traces_caustics) e.queues_per_worker += double(LightTracingPass::bytes_per_worker());
    const int lanes = intersect_kernels(options.isa.value_or(best_supported_isa()), s.accuracy).width;
    e.geometry = geometry_bytes(scene);
    if (resolve_accel(options.accel, scene.primitive_count(), lanes, !scene.instances.empty() || scene.has_alpha_materials) == Accel::bvh) {
        e.bvh = bvh_bytes(scene, options);
    } else {
        // The flat kernels' rows (triangle_rows.h): v0, the edges and the scaled normal, or
        // v0, the edges and the other two vertices.
        const double floats = s.accuracy.triangles == TriangleTest::watertight ? 15.0 : 12.0;
        e.geometry += double(scene.triangles.size()) * floats * sizeof(float);
    }
    if (scene.merges_photons) e.photons = photon_batch_bytes(scene, options.photon_batch_paths);
    e.instance_count = scene.instances.instances.size();
    if (e.instance_count > 0) e.instances = double(e.instance_count) * bytes_per_instance(options.bvh.node_width);
    e.textures = texture_bytes(scene);
    e.lights = double(scene.lights.bytes() + scene.emitter_selection.bytes() + scene.listed_lights.bytes());
    return e;
}

std::string format_bytes(double bytes) {
    const char* units[] = {"B", "kB", "MB", "GB", "TB"};
    int u = 0;
    while (bytes >= 1000.0 && u < 4) bytes /= 1000.0, ++u;
    char text[32];
    std::snprintf(text, sizeof text, u == 0 ? "%.0f %s" : "%.1f %s", bytes, units[u]);
    return text;
}

std::string texture_memory_line(const Scene& scene) {
    return "textures: " + std::to_string(scene.textures.size()) + (scene.textures.size() == 1 ? " image, " : " images, ") +
           format_bytes(texture_bytes(scene)) + " (mip levels of linear RGBA floats, and their coordinates)";
}

std::string geometry_memory_line(const Scene& scene) {
    double triangles = double(scene.triangles.size()), arrays = double(scene.triangles.bytes());
    double normals = double(scene.shading_normals.bytes());
    for (const InstancedMesh& m : scene.instances.meshes) {
        triangles += double(m.triangles.size()), arrays += double(m.triangles.bytes());
        normals += double(m.shading_normals.bytes());
    }
    const double per = std::max(1.0, triangles);
    char text[160];
    std::snprintf(text, sizeof text, "%.0f triangles: %s of primitive arrays (%.0f B each), %s of vertex normals (%.1f B a triangle)",
                  triangles, format_bytes(arrays).c_str(), arrays / per, format_bytes(normals).c_str(), normals / per);
    return text;
}

std::string memory_problem(const MemoryEstimate& e, double available) {
    if (available <= 0.0 || e.to_allocate() <= available) return {};
    std::ostringstream msg;
    msg << "the render needs about " << format_bytes(e.total()) << " (film " << format_bytes(e.film) << ", "
        << e.workers << " worker" << (e.workers > 1 ? "s" : "") << " x " << format_bytes(e.queues_per_worker)
        << " of wavefront queues, BVH " << format_bytes(e.bvh) << ", geometry " << format_bytes(e.geometry);
    if (e.photons > 0.0) msg << ", photon maps " << format_bytes(e.photons);
    if (e.instance_count > 0)
        msg << ", " << e.instance_count << " instances x " << format_bytes(e.instances / double(e.instance_count));
    if (e.textures > 0.0) msg << ", textures " << format_bytes(e.textures);
    if (e.lights > 0.0) msg << ", lights " << format_bytes(e.lights);
    msg << "), more than the " << format_bytes(available) << " of memory available; ";
    // Name what dominates.
    if (e.photons >= e.queues() && e.photons >= e.film && e.photons >= e.bvh && e.photons >= e.instances)
        msg << "lower --light-paths-per-pixel (a batch holds at least one sample's photons) or use --caustics light_tracing";
    else if (e.queues() >= e.film && e.queues() >= e.bvh)
        msg << "lower --shadow-rays, --tile-size or --batch-paths, or use fewer --threads";
    else if (e.film >= e.bvh && e.film >= e.instances)
        msg << "lower --width and --height";
    else if (e.instances > e.bvh)
        msg << "place fewer instances";
    else
        msg << "use --accel brute (no BVH, slower) or a smaller scene";
    return msg.str();
}

}  // namespace wt
