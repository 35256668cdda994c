#include "kernels/renderer.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "kernels/caustics/light_tracing_pass.h"
#include "kernels/adaptive/adaptive_range.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/memory_estimate.h"
#include "kernels/photons/photon_maps.h"
#include "kernels/reference_integrator.h"
#include "kernels/wavefront/wavefront_renderer.h"

namespace wt {

std::vector<std::string> render_film_channels(const Scene& scene, const AovSelection& aovs) {
    return film_channels_for(aovs, scene.light_traces_caustics);
}

int default_thread_count() { return std::max(1u, std::thread::hardware_concurrency()); }

namespace {

const RenderOptions& checked(const Scene& scene, const RenderOptions& options) {
    if (options.tile_size < 1) throw std::invalid_argument("render: tile size must be at least 1");
    if (options.batch_paths < 1) throw std::invalid_argument("render: batch size must be at least 1");
    if (options.photon_batch_paths < 1) throw std::invalid_argument("render: the photon batch must hold a light path");
    if (scene.settings.accuracy.triangles == TriangleTest::watertight && scene.triangles.parallelogram_count > 0)
        throw std::invalid_argument("render: the watertight triangle test cannot render parallelograms; build the scene "
                                    "with the accuracy settings it is rendered with");
    if (!scene.triangles.serves(scene.settings.accuracy.triangles))
        throw std::invalid_argument(std::string("render: the scene's triangles were stored for another triangle test than ") +
                                    name_of(scene.settings.accuracy.triangles) +
                                    "; build the scene with the accuracy settings it is rendered with");
    return options;
}

int thread_count(const RenderOptions& options) { return options.threads > 0 ? options.threads : default_thread_count(); }

}  // namespace

RenderSession::RenderSession(const Scene& scene, const RenderOptions& options)
    : scene_(scene), options_(checked(scene, options)), threads_(thread_count(options)),
      isa_(options.isa.value_or(best_supported_isa())),
      tiles_(make_tiles(scene.settings.width, scene.settings.height, options.tile_size)), pool_(threads_),
      kernels_(&intersect_kernels(isa_, scene.settings.accuracy)),
      counts_(std::size_t(threads_)), workspaces_(std::size_t(threads_)), sampled_pixels_(std::size_t(threads_)) {
    accel_ = resolve_accel(options.accel, scene.primitive_count(), kernels_->width,
                           !scene.instances.empty() || scene.has_alpha_materials);
    if (accel_ != Accel::bvh && !scene.instances.empty())
        throw std::invalid_argument("render: a scene with instances is traced through its BVH only; use --accel bvh or auto");
    if (accel_ != Accel::bvh && scene.has_alpha_materials)
        throw std::invalid_argument("render: a scene with alpha-tested materials (alphaMode MASK or BLEND) is traced "
                                    "through its BVH only; use --accel bvh or auto");
    if (accel_ == Accel::bvh) {
        BvhBuildOptions bvh_options = options.bvh;
        bvh_options.parallelograms_beside = parallelograms_beside_tree(kernels_->width);
        bvh_ = build_scene_bvh(scene, bvh_options, &pool_);
    } else {
        flat_ = std::make_unique<FlatScene>(scene);
    }
    if (scene.light_traces_caustics)
        light_tracing_ = std::make_unique<LightTracingPass>(scene, accel_ == Accel::bvh ? &bvh_.view : nullptr, threads_);
    if (scene.merges_photons) photons_ = std::make_unique<PhotonMaps>(scene);
}

RenderSession::~RenderSession() = default;

void RenderSession::render_samples(Film& film, SampleRange range, const std::function<void(uint64_t)>& tile_done) {
    if (film.width() != scene_.settings.width || film.height() != scene_.settings.height)
        throw std::invalid_argument("render: film resolution does not match the scene's");
    if (film.extra_channels() != render_film_channels(scene_, options_.aovs))
        throw std::invalid_argument("render: the film's extra channels are not those of the AOVs requested "
                                    "(and, with light tracing, the splats)");
    const AdaptiveSettings& adaptive = scene_.settings.adaptive;
    if (!adaptive.enabled() && !film.adaptive().empty())
        throw std::invalid_argument("render: the film is of a render with adaptive sampling, this scene has it off");
    if (range.end <= range.begin) return;

    const auto start = std::chrono::steady_clock::now();
    if (adaptive.enabled())
        render_adaptive_range(film, adaptive, range, &pool_,
                              [&](SampleRange piece) { render_camera_paths(film, piece, tile_done, &film.adaptive()); });
    else
        render_camera_paths(film, range, tile_done, nullptr);
    // The light paths of every sample of the range, whichever pixels still take samples: their
    // splats land anywhere and are normalised by the samples traced, never by a pixel's count.
    // (With photons they were traced batch by batch, before their camera paths.)
    if (light_tracing_ && !photons_) trace_light_paths(film, range, nullptr);
    if (photons_) photons_->release();
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

IntersectContext RenderSession::intersect_context() const {
    return {flat_ ? flat_->view() : SceneView{}, kernels_, flat_ ? nullptr : &bvh_.view};
}

void RenderSession::trace_light_paths(Film& film, SampleRange range, PhotonMaps* photons) {
    const IntersectContext context = intersect_context();
    light_tracing_->render(film, range.begin, range.end, pool_, counts_,
                           options_.integrator == Integrator::wavefront ? &context : nullptr, photons);
}

// With photons, a sample's camera paths need its photon map, so the range is cut into batches of
// a few samples (PhotonMaps::samples_per_batch): each batch's light paths first (their splats
// and photons), then its camera paths, then the photons go. The film's sums are exact, so the
// cut changes no bit of the image; every sample's light paths are still traced once.
void RenderSession::render_camera_paths(Film& film, SampleRange range, const std::function<void(uint64_t)>& tile_done,
                                        const AdaptiveState* adaptive) {
    if (!photons_) return render_tiles(film, range, tile_done, adaptive);
    const uint32_t step = PhotonMaps::samples_per_batch(options_.photon_batch_paths, light_paths_per_sample(scene_.settings));
    for (uint32_t begin = range.begin; begin < range.end;) {
        const SampleRange batch{begin, begin + std::min(step, range.end - begin)};
        trace_light_paths(film, batch, photons_.get());
        photons_->build_if_asked_before(pool_);
        render_tiles(film, batch, tile_done, adaptive);
        photons_->end_batch();
        begin = batch.end;
    }
}

void RenderSession::render_tiles(Film& film, SampleRange range, const std::function<void(uint64_t)>& tile_done,
                                 const AdaptiveState* adaptive) {
    const IntersectContext context = intersect_context();
    pool_.parallel_for(tiles_.size(), [&](std::size_t item, int worker) {
        const Tile& tile = tiles_[item];
        RayCounts& c = counts_[std::size_t(worker)];
        std::vector<uint32_t>& sampled = sampled_pixels_[std::size_t(worker)];
        if (adaptive) sampled_pixels_of_tile(*adaptive, tile, scene_.settings.width, sampled);
        const TilePixels pixels{sampled.data(), sampled.size()};
        if (adaptive && pixels.count == 0) {
            // Every pixel of the tile has stopped.
        } else if (options_.integrator == Integrator::reference) {
            if (adaptive)
                render_reference_pixels(scene_, pixels, range.begin, range.end, film, c, context.bvh, options_.aovs, photons_.get());
            else
                render_reference_tile(scene_, tile, range.begin, range.end, film, c, context.bvh, options_.aovs, photons_.get());
        } else {
            auto& ws = workspaces_[std::size_t(worker)];
            if (!ws) {
                const RenderSettings& s = scene_.settings;
                const std::size_t capacity = workspace_paths(s.width, s.height, s.spp, options_.tile_size, options_.batch_paths);
                ws = std::make_unique<WavefrontWorkspace>(capacity, std::size_t(scene_.settings.shadow_rays),
                                                          options_.aovs.needs_path_data(), !scene_.emitter_selection.empty());
            }
            if (adaptive)
                render_wavefront_pixels(scene_, context, tile, pixels, range.begin, range.end, options_.batch_paths,
                                        options_.aovs, *ws, film, c, photons_.get());
            else
                render_wavefront_tile(scene_, context, tile, range.begin, range.end, options_.batch_paths, options_.aovs,
                                      *ws, film, c, photons_.get());
        }
        if (tile_done) tile_done(uint64_t(tile.pixel_count()) * range.size());
    });
}

RenderResult RenderSession::result() const {
    RenderResult result;
    for (const RayCounts& c : counts_) result.counts += c;
    result.seconds = seconds_;
    result.threads = threads_;
    result.isa = isa_;
    result.accel = accel_;
    result.bvh = bvh_.tree.stats();
    if (bvh_.instances) {
        result.instance_count = bvh_.instances->instance_count();
        result.instanced_mesh_bytes = bvh_.instances->mesh_bytes();
        result.instance_bytes = bvh_.instances->instance_bytes() + scene_.instances.instances.size() * sizeof(Instance);
    }
    if (photons_) result.photon_maps_built = photons_->maps_built();
    return result;
}

RenderResult render(const Scene& scene, const RenderOptions& options, Film& film) {
    RenderSession session(scene, options);
    session.render_samples(film, {0, uint32_t(scene.settings.spp)});
    return session.result();
}

}  // namespace wt
