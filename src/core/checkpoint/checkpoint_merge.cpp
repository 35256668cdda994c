#include "core/checkpoint/checkpoint_merge.h"

#include <algorithm>
#include <optional>

#include "core/checkpoint/checkpoint_match.h"

namespace wt {

namespace {

struct PartRange {
    uint32_t first, next;
    const std::string* path;
};

std::string range_text(uint32_t begin, uint32_t end) { return std::to_string(begin) + ":" + std::to_string(end); }

}  // namespace

MergedCheckpoint merge_checkpoint_files(const std::vector<std::string>& paths) {
    if (paths.empty()) throw std::invalid_argument("merge: no partial renders given");
    std::optional<Checkpoint> sum;
    std::vector<PartRange> ranges;
    for (const std::string& path : paths) {
        Checkpoint part = read_checkpoint_file(path);
        ranges.push_back({part.header.first_sample, part.header.next_sample, &path});
        if (!sum) {
            sum.emplace(std::move(part));
            continue;
        }
        const std::vector<std::string> differences = checkpoint_differences(
            sum->header, layout_of(sum->film), paths[0], part.header, layout_of(part.film), path);
        if (!differences.empty())
            throw CheckpointError(describe_differences(path + " is not a part of the same render as " + paths[0], differences));
        // Its decisions needed all the samples before them in one film, so it has no parts.
        for (const auto* adaptive : {&*sum, &part})
            if (!adaptive->film.adaptive().empty())
                throw CheckpointError((adaptive == &part ? path : paths[0]) +
                                      " is a render with adaptive sampling, which cannot be merged with other parts");
        try {
            sum->film.add_film(part.film);
        } catch (const std::overflow_error& e) {
            throw CheckpointError(path + ": cannot be added to the parts before it: " + e.what());
        }
        sum->header.target_sample = std::max(sum->header.target_sample, part.header.target_sample);
    }

    // In sample order (ties by path, so the messages do not depend on the argument order).
    std::sort(ranges.begin(), ranges.end(), [](const PartRange& a, const PartRange& b) {
        return a.first != b.first ? a.first < b.first : a.next != b.next ? a.next < b.next : *a.path < *b.path;
    });
    // Empty parts hold nothing to overlap or to cover; an all-empty merge is the first part's range.
    ranges.erase(std::remove_if(ranges.begin(), ranges.end(), [](const PartRange& r) { return r.first == r.next; }),
                 ranges.end());
    MergedCheckpoint result{std::move(*sum), {}};
    if (ranges.empty()) return result;
    uint32_t covered = ranges[0].first;  // every sample in [ranges[0].first, covered) is in a part
    const PartRange* last = &ranges[0];
    for (const PartRange& r : ranges) {
        if (r.first < covered)
            throw CheckpointError(*last->path + " (samples " + range_text(last->first, last->next) + ") and " + *r.path +
                                  " (samples " + range_text(r.first, r.next) + ") overlap: samples " +
                                  range_text(r.first, std::min(covered, r.next)) + " would be counted twice");
        if (r.first > covered) result.gaps.push_back({covered, r.first});
        covered = r.next;
        last = &r;
    }
    result.merged.header.first_sample = ranges[0].first;
    result.merged.header.next_sample = covered;
    result.merged.header.target_sample = std::max(result.merged.header.target_sample, covered);
    return result;
}

}  // namespace wt
