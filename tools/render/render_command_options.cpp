#include "tools/render/render_command_options.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "core/description/adaptive_settings.h"
#include "core/description/estimator_settings.h"
#include "core/film/aov.h"
#include "kernels/accel/accel_choice.h"
#include "kernels/isa/isa.h"
#include "tools/cli/cli_values.h"

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
    std::vector<std::string> isas{"auto"}, accels;
    for (Isa isa : kAllIsas) isas.push_back(isa_name(isa));
    for (Accel accel : kAllAccels) accels.push_back(accel_name(accel));
    cmd->add_option("--isa", o.isa_name, "Intersection kernels: " + isa_names(", ") + " or auto (the best this CPU runs)")
        ->check(CLI::IsMember(isas));
    cmd->add_option("--accel", o.accel_name,
                    "Acceleration structure: auto (flat list for tiny scenes, else a BVH), bvh, or brute (flat list)")
        ->check(CLI::IsMember(accels));
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

}  // namespace wt
