#pragma once
// Whether two checkpoints (or a checkpoint and the render about to use it) are of the same
// image: the same scene content, resolution, channels and image-changing settings. Each
// difference is named, so a refusal says what to change.

#include <string>
#include <vector>

#include "core/checkpoint/checkpoint.h"

namespace wt {

struct FilmLayout {
    int width = 0, height = 0;
    std::vector<std::string> extra_channels;
};

FilmLayout layout_of(const Film& film);

// One line per difference, e.g. "seed: checkpoint 7, scene 8" or "size: a.ckpt 800x800,
// b.ckpt 200x200"; empty when they match. The sample ranges are not compared.
std::vector<std::string> checkpoint_differences(const CheckpointHeader& a, const FilmLayout& a_layout,
                                                const std::string& a_label, const CheckpointHeader& b,
                                                const FilmLayout& b_layout, const std::string& b_label);

// The lines joined into one message: "LEAD: line; line; ...".
std::string describe_differences(const std::string& lead, const std::vector<std::string>& lines);

}  // namespace wt
