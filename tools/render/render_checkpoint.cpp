#include "tools/render/render_checkpoint.h"

#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <sstream>

#include "core/film/aov.h"
#include "core/film/image_output.h"
#include "core/description/scene_hash.h"
#include "core/system/version.h"

namespace wt {

namespace fs = std::filesystem;

constexpr uint32_t max_sample_index = 1u << 20;  // as --spp

SampleRange parse_sample_range(const std::string& text) {
    std::istringstream in(text);
    long long begin = -1, end = -1;
    char colon = 0;
    in >> begin >> colon >> end;
    if (!in || colon != ':' || !(in >> std::ws).eof())
        throw std::runtime_error("--samples: expected BEGIN:END (two integers), got '" + text + "'");
    if (begin < 0 || end <= begin || end > max_sample_index)
        throw std::runtime_error("--samples " + text + ": need 0 <= BEGIN < END <= " + std::to_string(max_sample_index));
    return {uint32_t(begin), uint32_t(end)};
}

void check_checkpoint_path(const std::string& path, const std::string& option) {
    if (!is_checkpoint_path(path)) throw std::runtime_error(option + " " + path + ": a checkpoint's name must end in .ckpt");
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw std::runtime_error(option + " " + path + ": directory '" + dir.string() + "' does not exist");
    if (access(dir.c_str(), W_OK) != 0)
        throw std::runtime_error(option + " " + path + ": directory '" + dir.string() + "' is not writable");
}

CheckpointHeader checkpoint_header_for(uint64_t scene_hash, const RenderSettings& settings, SampleRange held,
                                       uint32_t target_sample) {
    return {program_version(), scene_hash, held.begin, held.end, target_sample, image_settings(settings)};
}

Checkpoint checkpoint_to_resume(const std::string& path, uint64_t scene_hash, const RenderSettings& settings,
                                const FilmLayout& layout) {
    Checkpoint checkpoint = read_checkpoint_file(path);
    const CheckpointHeader expected = checkpoint_header_for(scene_hash, settings, {}, 0);
    const std::vector<std::string> differences =
        checkpoint_differences(checkpoint.header, layout_of(checkpoint.film), "checkpoint", expected, layout, "this render");
    if (!differences.empty())
        throw CheckpointError(describe_differences(path + ": not a checkpoint of this render", differences));
    // The settings match, so only a damaged or hand-made file gets here without the state its
    // adaptive_threshold says it has.
    if (settings.adaptive.enabled() == checkpoint.film.adaptive().empty())
        throw CheckpointError(path + (settings.adaptive.enabled()
                                          ? ": has no adaptive sampling state, but its adaptive_threshold is not 0"
                                          : ": has adaptive sampling state, but its adaptive_threshold is 0"));
    return checkpoint;
}

ImageMetadata image_metadata_for(const CheckpointHeader& header, double render_seconds) {
    uint64_t seed = 0;
    for (const NamedSetting& s : header.settings)
        if (s.name == "seed") seed = std::stoull(s.value);
    return {header.next_sample - header.first_sample, seed, hash_to_hex(header.scene_hash), render_seconds,
            header.program_version};
}

void write_render_outputs(const std::vector<std::string>& outputs, const Film& film, const CheckpointHeader& header,
                          const AovSelection& aovs, const ImageMetadata& metadata) {
    const std::vector<float> rgb = film.resolve();
    const ImageChannels layers = resolve_aovs(film, aovs);
    for (const std::string& out : outputs) {
        if (is_checkpoint_path(out)) write_checkpoint_file(out, header, film);
        else write_image(out, film.width(), film.height(), rgb, &metadata, &layers);
    }
}

bool try_write_checkpoint(const std::string& path, const CheckpointHeader& header, const Film& film, bool announce) {
    try {
        write_checkpoint_file(path, header, film);
        if (announce) std::cerr << "wavetrace: checkpoint " << path << ": samples " << header.first_sample << ":" << header.next_sample << "\n";
        return true;
    } catch (const std::exception& e) {
        std::cerr << "wavetrace: warning: " << e.what() << " (the previous checkpoint stays)\n";
        return false;
    }
}

}  // namespace wt
