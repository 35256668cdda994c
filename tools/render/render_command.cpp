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
#include "tools/cli/cli_values.h"
#include "tools/render/debug_light_path.h"
#include "tools/render/debug_sample.h"
#include "tools/render/interrupt.h"
#include "tools/render/progress_display.h"
#include "tools/render/render_checkpoint.h"
#if WAVETRACE_MPI
#include "tools/render/mpi_render.h"
#include "tools/render/mpi_render_command.h"
#endif
#include "tools/render/render_passes.h"
#include "tools/render/render_summary.h"

namespace wt {

CLI::App* add_render_command(CLI::App& app, RenderCommandOptions& o) {
    CLI::App* cmd = app.add_subcommand("render", "Render a scene file to one or more images");
    cmd->add_option("scene", o.scene_path, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", o.outputs,
                    "Output image; repeat for several. .exr/.hdr: linear float, .png/.jpg: sRGB 8-bit "
                    "(default: SCENE's name with .png, in the current directory)");
    cmd->add_option("--spp", o.spp, "Samples per pixel")->transform(decimal_integer(1, 1 << 20));
    cmd->add_option("--shadow-rays", o.shadow_rays, "Shadow rays per diffuse hit")->transform(decimal_integer(1, 1024));
    cmd->add_option("--width", o.width, "Image width in pixels")->transform(decimal_integer(1, 65536));
    cmd->add_option("--height", o.height, "Image height in pixels")->transform(decimal_integer(1, 65536));
    cmd->add_option("--seed", o.seed, "Random seed")->transform(decimal_integer(0, UINT64_MAX));
    cmd->add_option("--threads", o.render.threads, "Worker threads (default: one per hardware thread)")
        ->transform(decimal_integer(1, 1024));
    cmd->add_option("--integrator", o.integrator_name, "wavefront (fast) or reference (scalar per-path oracle)")
        ->check(CLI::IsMember({"wavefront", "reference"}));
    cmd->add_option("--triangle-test", o.triangle_test, "moller_trumbore (fast) or watertight (no leaks at shared edges)")
        ->check(CLI::IsMember({"moller_trumbore", "watertight"}));
    cmd->add_option("--sphere-test", o.sphere_test, "quadratic (fast) or cancellation_free (small and distant spheres)")
        ->check(CLI::IsMember({"quadratic", "cancellation_free"}));
    cmd->add_option("--fresnel", o.fresnel, "schlick (approximation) or exact (dielectric Fresnel equations)")
        ->check(CLI::IsMember({"schlick", "exact"}));
    cmd->add_option("--multiple-scattering", o.multiple_scattering,
                    "none (rough metals lose the light single scattering cannot return) or kulla_conty "
                    "(a lobe gives it back: rough conductors and the principled material's specular lobe)")
        ->check(CLI::IsMember({"none", "kulla_conty"}));
    cmd->add_option("--sampler", o.sampler, "stratified (jittered pixel), independent, or sobol (Owen-scrambled Sobol')")
        ->check(CLI::IsMember({"independent", "stratified", "sobol"}));
    cmd->add_option("--light-sampling", o.light_sampling, "nee (light samples only) or mis (light and BSDF samples, power heuristic)")
        ->check(CLI::IsMember({"nee", "mis"}));
    cmd->add_option("--light-selection", o.light_selection,
                    "which emissive triangle a light sample goes to: area (in proportion to area), power (to "
                    "area x luminance), bvh (a light tree: power, distance and orientation from the shading point) or "
                    "auto (the default: power where a scene has 16 emitters or more whose radiance differs, else area)")
        ->check(CLI::IsMember({"auto", "area", "power", "bvh"}));
    cmd->add_option("--caustics", o.caustics,
                    "Caustics (diffuse, mirror or glass, light): path (the camera path finds them by chance), "
                    "light_tracing (light paths through the mirrors and glass, connected to the camera, for caustics "
                    "seen directly) or photons (light_tracing, and the same paths as photons for caustics seen through "
                    "a mirror or glass; the default where a scene has a light and a mirror or glass surface)")
        ->check(CLI::IsMember({"path", "light_tracing", "photons"}));
    cmd->add_option("--light-paths-per-pixel", o.light_paths_per_pixel,
                    "With light tracing: light paths per sample, per pixel of the image (default 1)")
        ->check(CLI::Range(1.0 / 1024, 64.0));
    cmd->add_option("--photon-radius", o.photon_radius,
                    "With photons: the lookup radius of sample 0 in scene units, shrinking with later samples "
                    "(default: automatic, two pixels' footprint at the scene's distance)")
        ->check(non_negative_float())
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                const double r = std::stod(text);  // a number: non_negative_float checked it
                if (r > 0.0 && r <= double(kPhotonRadiusMax)) return {};
                return "expected a radius greater than 0 and at most 1e18, got '" + text + "'";
            },
            "RADIUS > 0"));
    cmd->add_option("--clamp-indirect", o.clamp_indirect, "Limit each indirect contribution to X per channel (0: off)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--adaptive-threshold", o.adaptive_threshold,
                    "Adaptive sampling: a pixel stops once its error and its neighbours' are below X (0: off)")
        ->check(non_negative_float());
    cmd->add_option("--adaptive-min-spp", o.adaptive_min_spp, "Adaptive sampling: no pixel stops before N samples")
        ->transform(decimal_integer(adaptive_min_spp_lowest, 1 << 20));
    cmd->add_option("--isa", o.isa_name, "Intersection kernels: scalar, sse4, avx2, avx512 or auto (the best this CPU runs)")
        ->check(CLI::IsMember({"auto", "scalar", "sse4", "avx2", "avx512"}));
    cmd->add_option("--accel", o.accel_name,
                    "Acceleration structure: auto (flat list for tiny scenes, else a BVH), bvh, or brute (flat list)")
        ->check(CLI::IsMember({"auto", "bvh", "brute"}));
    cmd->add_option("--bvh-width", o.render.bvh.node_width, "Children per BVH node: 4 or 8")->transform(decimal_integer(4, 8))->check(CLI::IsMember({4, 8}));
    cmd->add_option("--tile-size", o.render.tile_size, "Tile side in pixels")->transform(decimal_integer(1, 65536));
    cmd->add_option("--batch-paths", o.render.batch_paths, "Camera paths per wavefront batch")
        ->transform(decimal_integer(1, uint64_t(1) << 24));
    cmd->add_option("--debug-sample", o.debug_sample,
                    "X,Y,S: trace only sample S of pixel (X,Y) with the reference integrator and print every vertex");
    cmd->add_option("--debug-light-path", o.debug_light_path,
                    "I,S: with light tracing, trace only light path I of sample S and print every vertex and its "
                    "connection to the camera");
    cmd->add_option("--time-limit", o.time_limit,
                    "Stop at the last pass boundary within SECONDS of rendering and write the image it has "
                    "(the spp it reached is printed and in the image's metadata)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--write-every", o.write_every, "Also write the outputs every SECONDS, at pass boundaries")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--checkpoint", o.checkpoint,
                    "Save the render's state to FILE (.ckpt) every --checkpoint-every seconds, at the end and when "
                    "interrupted, for --resume (default with --resume: the resumed file)");
    cmd->add_option("--checkpoint-every", o.checkpoint_every, "Seconds between checkpoints (default 300)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--resume", o.resume,
                    "Continue the render saved in FILE, to its spp or to a larger --spp; the scene and settings must "
                    "be those it was started with");
    cmd->add_option("--samples", o.samples,
                    "BEGIN:END: render only samples BEGIN to END-1 of every pixel, a part of a split render for "
                    "`wavetrace merge` (default output: SCENE.BEGIN-END.ckpt)");
    cmd->add_option("--aov", o.aov_list,
                    "Extra layers in .exr outputs, comma-separated: albedo, normal, depth, variance, samples, or all")
        ->check(CLI::Validator(
            [](std::string& text) {
                try {
                    parse_aov_list(text);
                    return std::string();
                } catch (const std::invalid_argument& e) {
                    return std::string(e.what());
                }
            },
            "AOV,...", "AOV list"));
    add_reference_error_options(*cmd, o.error);
    cmd->add_flag("-q,--quiet", o.quiet, "Print nothing but errors (no progress, no summary)");
    return cmd;
}

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
            if (is_checkpoint_path(out)) check_checkpoint_path(out, "-o");
            else check_output_path(out);
        if (o.checkpoint) check_checkpoint_path(*o.checkpoint, "--checkpoint");
        if (!std::all_of(o.outputs.begin(), o.outputs.end(), is_checkpoint_path)) check_image_writer_available();
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
