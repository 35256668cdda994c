#include "tools/merge/merge_command.h"

#include <iostream>
#include <memory>

#include "core/checkpoint/checkpoint_merge.h"
#include "core/film/aov.h"
#include "core/film/image_output.h"
#include "tools/render/render_checkpoint.h"

namespace wt {

CLI::App* add_merge_command(CLI::App& app, MergeCommandOptions& o) {
    CLI::App* cmd = app.add_subcommand("merge", "Combine partial renders (render --samples) into one image or checkpoint");
    cmd->add_option("parts", o.parts, "Partial renders (.ckpt) of disjoint sample ranges of one render")->required();
    cmd->add_option("-o,--output", o.outputs, "Output: an image (.exr, .hdr, .png, .jpg) or a checkpoint (.ckpt); repeatable")
        ->required();
    cmd->add_flag("--allow-gaps", o.allow_gaps,
                  "Write images even when samples between the parts are missing (each pixel is then the mean of the "
                  "samples it has; a checkpoint cannot be written, since it would claim samples it lacks)");
    cmd->add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
    return cmd;
}

namespace {

std::string range_text(uint32_t begin, uint32_t end) { return std::to_string(begin) + ":" + std::to_string(end); }

}  // namespace

int run_merge_command(const MergeCommandOptions& o) {
    try {
        bool checkpoint_output = false;
        for (const std::string& out : o.outputs) {
            if (is_checkpoint_path(out)) check_checkpoint_path(out, "-o"), checkpoint_output = true;
            else check_output_path(out);
        }
        const MergedCheckpoint m = merge_checkpoint_files(o.parts);
        const CheckpointHeader& h = m.merged.header;
        if (!m.gaps.empty()) {
            std::string missing;
            for (const SampleGap& g : m.gaps) missing += (missing.empty() ? "" : ", ") + range_text(g.begin, g.end);
            if (!o.allow_gaps)
                throw std::runtime_error("samples " + missing + " are in none of the parts (render them with --samples, "
                                         "or pass --allow-gaps to write an image of the samples there are)");
            if (checkpoint_output)
                throw std::runtime_error("samples " + missing + " are missing: a checkpoint of samples " +
                                         range_text(h.first_sample, h.next_sample) + " would claim them");
            std::cerr << "wavetrace: warning: samples " << missing << " are in none of the parts\n";
        }
        if (h.first_sample > 0 && !o.quiet)
            std::cerr << "wavetrace: note: the parts start at sample " << h.first_sample << ": samples "
                      << range_text(0, h.first_sample) << " are not in them\n";
        uint32_t spp = h.next_sample - h.first_sample;
        for (const SampleGap& g : m.gaps) spp -= g.end - g.begin;
        // The images claim only the samples there are; the parts do not record their render times: 0.
        ImageMetadata metadata = image_metadata_for(h, 0.0);
        metadata.spp = spp;
        write_render_outputs(o.outputs, m.merged.film, h, aovs_held_by(m.merged.film), metadata);
        if (!o.quiet) {
            std::cout << "wavetrace: merged " << o.parts.size() << " part" << (o.parts.size() > 1 ? "s" : "") << ", samples "
                      << range_text(h.first_sample, h.next_sample) << " (" << spp << " spp), " << m.merged.film.width()
                      << "x" << m.merged.film.height() << "\n";
            for (const std::string& out : o.outputs) std::cout << "  wrote            " << out << "\n";
        }
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "wavetrace: error: " << e.what() << "\n";
        return 1;
    }
}

Subcommand merge_subcommand(CLI::App& app) {
    auto options = std::make_shared<MergeCommandOptions>();
    return {add_merge_command(app, *options), [options] { return run_merge_command(*options); }};
}

}  // namespace wt
