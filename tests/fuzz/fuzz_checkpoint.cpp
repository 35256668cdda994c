// libFuzzer target: bytes through the checkpoint reader (parse_checkpoint), with and without
// the checksum: random bytes never pass it, so the decoder behind it is fuzzed with the check
// off too. The input's program version is first made this program's (checkpoint_rewrite.h), so
// the seeds reach the film's decoder after a version bump. Anything but a CheckpointError is a
// finding.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/checkpoint/checkpoint.h"
#include "checkpoint_rewrite.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string bytes = wt::test::with_this_program_version(std::string_view(reinterpret_cast<const char*>(data), size));
    for (bool verify : {true, false}) {
        try {
            const wt::Checkpoint checkpoint = wt::parse_checkpoint(bytes, "fuzz.ckpt", verify);
            (void)checkpoint;
        } catch (const wt::CheckpointError&) {
        }
    }
    return 0;
}
