#pragma once
// `wavetrace render`'s options, as parsed from the command line, and their declaration on it.
// Kept apart from the command that runs them (render_command.h), so that parsing a command line
// needs none of the renderer's code: the fuzz target fuzz_cli parses one without building the
// kernels (tools/CMakeLists.txt, wavetrace_command_line). RenderOptions is a plain struct of
// kernels/renderer.h: its header is included, nothing of the kernels is linked.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "kernels/render_options.h"
#include "tools/render/reference_error_options.h"

namespace wt {

struct RenderCommandOptions {
    std::string scene_path;
    std::vector<std::string> outputs;
    // Overrides of the scene's render settings; unset means "as the scene says".
    std::optional<int> spp, shadow_rays, width, height;
    std::optional<uint64_t> seed;
    std::optional<std::string> triangle_test, sphere_test, fresnel, multiple_scattering;
    std::optional<std::string> sampler, light_sampling, light_selection, caustics;
    std::optional<float> clamp_indirect;
    std::optional<double> light_paths_per_pixel;
    std::optional<float> photon_radius;
    std::optional<float> adaptive_threshold;
    std::optional<int> adaptive_min_spp;
    RenderOptions render;
    std::string integrator_name = "wavefront";
    std::string isa_name = "auto";
    std::string accel_name = "auto";
    std::optional<std::string> debug_sample;  // "X,Y,S": replay one sample instead of rendering
    std::optional<std::string> debug_light_path;  // "I,S": replay one light path instead of rendering
    std::optional<double> time_limit, write_every;  // seconds
    std::optional<std::string> checkpoint, resume, samples;  // samples: "BEGIN:END", a partial render
    double checkpoint_every = 300.0;                         // seconds
    std::string aov_list;                           // --aov: "albedo,normal,..." or "all"; empty: none
    ReferenceErrorOptions error;                    // --reference, --error-csv
    bool quiet = false;
};

// Registers the subcommand's options on `app`, writing into `options`.
CLI::App* add_render_command(CLI::App& app, RenderCommandOptions& options);

}  // namespace wt
