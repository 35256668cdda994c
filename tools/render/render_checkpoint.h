#pragma once
// Checkpoints and partial renders in `wavetrace render`: the header this render writes, the
// checks before a resume, the --samples range, and writing a checkpoint without stopping the
// render when the disk says no.

#include <optional>
#include <string>
#include <vector>

#include "core/checkpoint/checkpoint.h"
#include "core/checkpoint/checkpoint_match.h"
#include "core/film/image_output.h"
#include "kernels/render_options.h"
#include "kernels/work/sample_range.h"

namespace wt {

// "BEGIN:END", 0 <= BEGIN < END <= 2^20. Throws std::runtime_error naming --samples.
SampleRange parse_sample_range(const std::string& text);

// A .ckpt name in a directory that exists and is writable; std::runtime_error naming `option`.
void check_checkpoint_path(const std::string& path, const std::string& option);

CheckpointHeader checkpoint_header_for(uint64_t scene_hash, const RenderSettings& settings, SampleRange held,
                                       uint32_t target_sample);

// Reads the checkpoint at `path` for a resume of this scene with `settings` (the scene's, with
// the command line's overrides): everything must match, else CheckpointError lists each
// difference.
Checkpoint checkpoint_to_resume(const std::string& path, uint64_t scene_hash, const RenderSettings& settings,
                                const FilmLayout& layout);

// The metadata of an image of a film that `header` describes (its spp: the samples it holds).
ImageMetadata image_metadata_for(const CheckpointHeader& header, double render_seconds);

// Writes every output of a render, images (with `aovs` in EXR files, and `metadata`) and
// checkpoints (.ckpt; `header` says what they hold). Throws on the first failure, naming the file.
void write_render_outputs(const std::vector<std::string>& outputs, const Film& film, const CheckpointHeader& header,
                          const AovSelection& aovs, const ImageMetadata& metadata);

// Writes `film` to `path` (saying so on stderr if `announce`); on failure prints a warning
// (the previous file stays, the render goes on) and returns false.
bool try_write_checkpoint(const std::string& path, const CheckpointHeader& header, const Film& film, bool announce);

}  // namespace wt
