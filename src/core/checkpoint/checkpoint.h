#pragma once
// A film saved with what it is a film of: the checkpoint of an interrupted render, the partial
// result of one sample range of a split render, or the merge of partials. One format for all
// three, so any of them can be resumed, merged or turned into an image.
//
// The file (all integers little-endian; layout details in checkpoint_format.h):
//   magic "\x89WTCKPT\n", format version (u32), length of the text header (u32)
//   text header: "key value" lines: program version, scene content hash, the sample ranges,
//                the image-changing settings by name, the film's size and channels
//   per pixel: its sample count (u32) and its sums (fixed point, 8 or 16 bytes per channel)
//   XXH3-64 checksum of every byte before it
// The sums are the film's exact fixed-point integers (fixed_point.h), so a film written and
// read back is the same bits, and resuming from it is bit-identical to never having stopped.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/checkpoint/checkpoint_settings.h"
#include "core/film/film.h"

namespace wt {

// Everything a checkpoint says besides the film's sums and counts.
struct CheckpointHeader {
    std::string program_version;
    uint64_t scene_hash = 0;
    // The film holds samples [first_sample, next_sample) of every pixel (a pixel may have fewer:
    // non-finite samples are dropped, fixed_point.h). The render it belongs to was asked for
    // [first_sample, target_sample): a resume continues to there unless told otherwise.
    uint32_t first_sample = 0, next_sample = 0, target_sample = 0;
    std::vector<NamedSetting> settings;  // image_settings(): what must match to resume or merge
};

struct Checkpoint {
    CheckpointHeader header;
    Film film;
};

// A file that is not a checkpoint this program can use. The message names the file, and the
// byte offset where that helps.
struct CheckpointError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Decodes a whole checkpoint from memory; `name` (a path) is what messages call it. Every
// size is checked against the bytes there before anything is allocated, so a hostile or
// damaged file costs at most about twice its own size in memory (the film): the reader a fuzz
// target calls. Throws CheckpointError. `verify_checksum` false is for fuzzing only: random
// bytes never pass the checksum, so the decoder behind it would go untested.
Checkpoint parse_checkpoint(std::string_view bytes, const std::string& name, bool verify_checksum = true);
// Reads and parses `path`. Throws CheckpointError (including when it cannot be read).
Checkpoint read_checkpoint_file(const std::string& path);

// The encoding, for tests and fuzz seeds. Throws std::invalid_argument for a header the format
// cannot hold (a setting or channel name with white space, an inconsistent sample range).
std::string checkpoint_bytes(const CheckpointHeader& header, const Film& film);
// Writes `path` atomically (core/system/atomic_file.h): on any failure (disk full, unwritable
// directory) FileWriteError is thrown and the file that was there is untouched.
void write_checkpoint_file(const std::string& path, const CheckpointHeader& header, const Film& film);

// Whether `path` names a checkpoint rather than an image (its extension is `.ckpt`).
bool is_checkpoint_path(const std::string& path);

}  // namespace wt
