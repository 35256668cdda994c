#include "tools/render/render_command.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "core/checkpoint/checkpoint.h"
#include "core/film/aov.h"
#include "core/film/film.h"
#include "core/film/image_output.h"
#include "core/base/printable.h"
#include "core/scene/scene.h"
#include "core/scene_file/scene_loader.h"
#include "core/description/scene_hash.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/memory_estimate.h"
#include "kernels/progressive_render.h"
#include "tools/render/debug_light_path.h"
#include "tools/render/debug_sample.h"
#include "tools/render/interrupt.h"
#include "tools/render/progress_display.h"
#include "tools/render/reference_error.h"
#include "tools/render/render_checkpoint.h"
#if WAVETRACE_MPI
#include "tools/render/mpi_render.h"
#include "tools/render/mpi_render_command.h"
#endif
#include "tools/render/render_passes.h"
#include "tools/render/render_summary.h"

namespace wt {

namespace {

void apply_overrides(const RenderCommandOptions& o, RenderSettings& s) {
    if (o.spp) s.spp = *o.spp;
    if (o.shadow_rays) s.shadow_rays = *o.shadow_rays;
    if (o.width) s.width = *o.width;
    if (o.height) s.height = *o.height;
    if (o.seed) s.seed = *o.seed;
    // The CLI checked membership already, so parsing cannot fail here.
    if (o.triangle_test) s.accuracy.triangles = *parse_triangle_test(*o.triangle_test);
    if (o.sphere_test) s.accuracy.spheres = *parse_sphere_test(*o.sphere_test);
    if (o.fresnel) s.accuracy.fresnel = *parse_fresnel_model(*o.fresnel);
    if (o.multiple_scattering) s.accuracy.multiple_scattering = *parse_multiple_scattering(*o.multiple_scattering);
    if (o.sampler) s.estimator.sampler = *parse_sampler(*o.sampler);
    if (o.light_sampling) s.estimator.light_sampling = *parse_light_sampling(*o.light_sampling);
    if (o.light_selection) s.estimator.light_selection = *parse_light_selection(*o.light_selection);
    if (o.clamp_indirect) s.estimator.clamp_indirect = *o.clamp_indirect;
    if (o.caustics) s.estimator.caustics = *parse_caustic_paths(*o.caustics);
    if (o.light_paths_per_pixel) s.estimator.light_paths_per_pixel = float(*o.light_paths_per_pixel);
    if (o.photon_radius) s.estimator.photon_radius = *o.photon_radius;
    if (o.adaptive_threshold) s.adaptive.threshold = *o.adaptive_threshold;
    if (o.adaptive_min_spp) s.adaptive.min_spp = *o.adaptive_min_spp;
}

// Adaptive sampling decides at each decision point from the whole film, all samples before it
// included: a part of a split render, or a rank's chunks, does not have them.
void check_adaptive_combinations(const RenderCommandOptions& o, const RenderSettings& s) {
    if (!s.adaptive.enabled()) return;
    if (o.samples)
        throw std::runtime_error("--samples " + *o.samples +
                                 ": a render with adaptive sampling cannot be split into sample ranges (its stopping "
                                 "decisions need every sample before them in one film); render it in one process, with "
                                 "--checkpoint and --resume to stop and continue, or set --adaptive-threshold 0");
#if WAVETRACE_MPI
    if (MpiJob::active())
        throw std::runtime_error("adaptive sampling is not supported under mpirun (its stopping decisions need the whole "
                                 "film at every decision point); run without mpirun, or set --adaptive-threshold 0");
#endif
}

std::string default_output(const RenderCommandOptions& o, SampleRange part) {
    const std::string stem = std::filesystem::path(o.scene_path).stem().string();
    if (!o.samples) return stem + ".png";
    return stem + "." + std::to_string(part.begin) + "-" + std::to_string(part.end) + ".ckpt";
}

}  // namespace

int run_render_command(RenderCommandOptions& o) {
    try {
        SceneDescription description = load_scene_file(o.scene_path);
        if (!o.quiet)
            for (const std::string& note : description.notes) std::cerr << "wavetrace: note: " << note << "\n";
        apply_overrides(o, description.settings);
        check_adaptive_combinations(o, description.settings);
        if (o.resume && o.samples) throw std::runtime_error("--resume continues the range it holds: no --samples with it");
        // A partial render's samples; otherwise [0, spp).
        const SampleRange part = o.samples ? parse_sample_range(*o.samples) : SampleRange{};
        const uint64_t scene_hash = scene_content_hash(description);
        if (!o.aov_list.empty()) o.render.aovs = parse_aov_list(o.aov_list);  // the CLI checked it
        const std::vector<std::string> film_channels = film_channels_for(o.render.aovs, light_traces_caustics(description));
        std::optional<Checkpoint> resumed;
        if (o.resume) {
            RenderSettings& s = description.settings;
            // The AOVs are part of the film: a resume asks for the ones the checkpoint holds.
            resumed = checkpoint_to_resume(*o.resume, scene_hash, s, {s.width, s.height, film_channels});
            const CheckpointHeader& h = resumed->header;
            if (!o.spp && h.first_sample == 0) s.spp = int(h.target_sample);
            if (o.spp && uint32_t(*o.spp) < h.next_sample)
                throw std::runtime_error("--spp " + std::to_string(*o.spp) + ": " + *o.resume + " holds samples up to " +
                                         std::to_string(h.next_sample) + " already");
            if (!o.checkpoint) o.checkpoint = *o.resume;
        }
        const RenderSettings settings = description.settings;
        const Scene scene = build_scene(description);
        description = SceneDescription();  // a big mesh's vertices and indices are in the scene now
        if (scene.has_textures() && !o.quiet) std::cerr << "wavetrace: " << texture_memory_line(scene) << "\n";

        o.render.accel = *parse_accel(o.accel_name);  // CLI checked membership
        if (o.debug_sample)
            return replay_sample(scene, o.render, parse_debug_sample(*o.debug_sample, settings.width, settings.height));
        if (o.debug_light_path)
            return replay_light_path(scene, o.render, parse_debug_light_path(*o.debug_light_path, scene));

        if (o.outputs.empty()) o.outputs.push_back(default_output(o, part));
#if WAVETRACE_MPI
        if (MpiJob::active()) check_mpi_render_options(o);
#endif
        for (const std::string& out : o.outputs)
            if (is_checkpoint_path(out)) {
                check_checkpoint_path(out, "-o");
            } else {
                check_output_path(out);
                check_image_writer_available(out);
            }
        if (o.checkpoint) check_checkpoint_path(*o.checkpoint, "--checkpoint");
        if (o.render.aovs.any() && !o.quiet && std::none_of(o.outputs.begin(), o.outputs.end(), holds_layers))
            std::cerr << "wavetrace: note: --aov layers are written to .exr outputs only, and none was given\n";
        o.render.integrator = o.integrator_name == "reference" ? Integrator::reference : Integrator::wavefront;
        if (o.isa_name != "auto") {
            o.render.isa = parse_isa(o.isa_name);
            if (!cpu_supports(*o.render.isa)) throw std::runtime_error("--isa " + o.isa_name + ": this CPU does not support it");
        }
        const std::string memory = memory_problem(estimate_render_memory(scene, o.render), available_memory_bytes());
        if (!memory.empty()) throw std::runtime_error(memory);
        ReferenceErrorLog error_log(o.error, settings.width, settings.height);
        RenderSession session(scene, o.render);
#if WAVETRACE_MPI
        if (MpiJob::active())
            return run_render_on_mpi_ranks(o, session, scene, checkpoint_header_for(scene_hash, settings, {0, 0}, 0));
#endif
        // The samples [first, next) the film holds, and [next, target) still to render.
        const uint32_t first = resumed ? resumed->header.first_sample : part.begin;
        const uint32_t next = resumed ? resumed->header.next_sample : first;
        const uint32_t target = o.samples ? part.end
                                : o.spp || !resumed ? uint32_t(settings.spp)
                                                    : resumed->header.target_sample;
        Film film = resumed ? std::move(resumed->film) : Film(settings.width, settings.height, film_channels);
        resumed.reset();
        const auto header_at = [&](uint32_t next_sample) {
            return checkpoint_header_for(scene_hash, settings, {first, next_sample}, target);
        };

        ProgressiveOptions passes;
        passes.samples = {next, target};
        passes.film_first_sample = first;
        passes.time_limit = o.time_limit.value_or(0.0);
        // Short enough that Ctrl-C, --write-every, checkpoints and the time limit are answered promptly.
        passes.pass_seconds = std::min({2.0, o.write_every.value_or(2.0), o.checkpoint ? o.checkpoint_every : 2.0});
        passes.stop = &interrupt_requested();
        ProgressDisplay progress(progress_style_for_stderr(o.quiet), film.pixel_total(), next - first, target - first,
                                 passes.time_limit);
        RenderPassHooks hooks(progress);
        if (o.write_every)
            hooks.every(*o.write_every, [&](const Film& current, const PassReport& report) {
                try {
                    const CheckpointHeader header = header_at(report.pass_samples.end);
                    write_render_outputs(o.outputs, current, header, o.render.aovs, image_metadata_for(header, report.seconds));
                } catch (const std::exception& e) {
                    // The previous images stay in place; the render goes on and tries again later.
                    std::cerr << "wavetrace: warning: " << e.what() << " (rendering continues)\n";
                }
            });
        if (o.checkpoint)
            hooks.every(o.checkpoint_every, [&](const Film& current, const PassReport& report) {
                try_write_checkpoint(*o.checkpoint, header_at(report.pass_samples.end), current, !o.quiet);
            });
        error_log.attach(hooks, session, o.quiet ? nullptr : &std::cerr);
        install_interrupt_handlers();
        const ProgressiveResult passes_done = render_progressive(session, film, passes, &hooks);
        progress.finish();

        // The checkpoint first, so a render whose image cannot be written can still be resumed;
        // the images even when the checkpoint cannot be, so the samples are not all lost.
        const CheckpointHeader final_header = header_at(passes_done.end_sample);
        const bool checkpointed = !o.checkpoint || try_write_checkpoint(*o.checkpoint, final_header, film, false);
        write_render_outputs(o.outputs, film, final_header, o.render.aovs,
                             image_metadata_for(final_header, session.result().seconds));
        if (!checkpointed) throw std::runtime_error(*o.checkpoint + ": the final checkpoint could not be written (the images were)");
        if (!o.quiet) {
            std::vector<std::string> written = o.outputs;
            if (o.checkpoint) written.push_back(*o.checkpoint);
            RenderSummary summary{o.scene_path, o.integrator_name, &scene, &o.render, session.result(), passes_done,
                                  passes_done.end_sample - first, written, &film.adaptive()};
            print_render_summary(std::cout, summary);
        }
        error_log.finish(session.result().seconds, passes_done.end_sample - first, film, o.quiet ? nullptr : &std::cout);
        return passes_done.reason == StopReason::interrupted ? exit_interrupted : 0;
    } catch (const std::exception& e) {
        std::cerr << "wavetrace: error: " << printable(e.what()) << "\n";
#if WAVETRACE_MPI
        if (MpiJob::active()) MpiJob::abort(1);  // the other ranks would wait for this one forever
#endif
        return 1;
    }
}

Subcommand render_subcommand(CLI::App& app) {
    auto options = std::make_shared<RenderCommandOptions>();
    return {add_render_command(app, *options), [options] { return run_render_command(*options); }};
}

}  // namespace wt
