#include "tools/render/mpi_render_command.h"

#include <iostream>
#include <stdexcept>

#include "core/description/scene_hash.h"
#include "tools/render/mpi_render.h"
#include "tools/render/render_checkpoint.h"
#include "tools/render/render_summary.h"

namespace wt {

void check_mpi_render_options(const RenderCommandOptions& o) {
    // Each of these is a single-process feature today; under mpirun it would be silently wrong.
    const auto refuse = [](const char* option) {
        throw std::runtime_error(std::string(option) + " is not supported under mpirun (run without mpirun, or split "
                                                       "the render with --samples and merge)");
    };
    if (o.resume) refuse("--resume");
    if (o.checkpoint) refuse("--checkpoint");
    if (o.samples) refuse("--samples");
    if (o.time_limit) refuse("--time-limit");
    if (o.write_every) refuse("--write-every");
    if (!o.aov_list.empty()) refuse("--aov");
}

int run_render_on_mpi_ranks(const RenderCommandOptions& o, RenderSession& session, const Scene& scene,
                            CheckpointHeader header) {
    const RenderSettings& settings = scene.settings;
    Film film(settings.width, settings.height, render_film_channels(scene, AovSelection{}));
    const SampleRange samples{0, uint32_t(settings.spp)};
    std::string identity = "scene " + hash_to_hex(header.scene_hash) + ", " + std::to_string(settings.width) + "x" +
                           std::to_string(settings.height) + ", spp " + std::to_string(settings.spp);
    for (const NamedSetting& s : header.settings) identity += ", " + s.name + " " + s.value;
    const DistributedRenderResult r = render_distributed(session, film, samples, identity, o.quiet);
    if (MpiJob::rank() != 0) return 0;

    header.first_sample = samples.begin, header.next_sample = header.target_sample = samples.end;
    write_render_outputs(o.outputs, film, header, AovSelection{}, image_metadata_for(header, r.seconds));
    if (!o.quiet) {
        RenderResult result = session.result();
        result.counts = r.counts;
        result.seconds = r.seconds;
        ProgressiveResult chunks;
        chunks.end_sample = samples.end;
        chunks.passes = r.chunks;
        chunks.seconds = r.seconds;
        print_render_summary(std::cout, {o.scene_path, o.integrator_name, &scene, &o.render, result, chunks,
                                         samples.size(), o.outputs});
        std::cout << "  MPI              " << MpiJob::size() << " ranks, " << r.chunks << " chunks of samples\n";
    }
    return 0;
}

}  // namespace wt
