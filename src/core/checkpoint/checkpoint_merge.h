#pragma once
// Combining the partial results of a split render (checkpoints of disjoint sample ranges of
// the same image) into one. The films' sums are exact, so the result is the same bits in any
// order of the parts, and the same bits as one render of all their samples.

#include <cstdint>
#include <string>
#include <vector>

#include "core/checkpoint/checkpoint.h"

namespace wt {

struct SampleGap {
    uint32_t begin = 0, end = 0;  // samples [begin, end) are in no part
};

struct MergedCheckpoint {
    // The sum of every part. Its header's range is [lowest first sample, highest next sample):
    // true only when `gaps` is empty.
    Checkpoint merged;
    std::vector<SampleGap> gaps;  // between the parts' ranges, in order (not before the first)
};

// Reads every file (one at a time, so memory holds two films) and adds them. Throws
// CheckpointError naming the files when one cannot be read, does not match the first (scene,
// settings, size, channels, version), is of an adaptive render and not alone (its decisions
// needed all samples before them in one film), or when two ranges overlap, and
// std::invalid_argument for an empty list.
MergedCheckpoint merge_checkpoint_files(const std::vector<std::string>& paths);

}  // namespace wt
