#pragma once
// The byte layout of a checkpoint (checkpoint.h), shared by its writer and its reader.
//
//   offset 0   magic, 8 bytes: "\x89WTCKPT\n" (a high-bit byte and a line feed, as PNG's, so a
//              transfer that strips the 8th bit or converts line ends is caught at once)
//   offset 8   format version, u32
//   offset 12  length H of the text header, u32 (at most max_header_bytes)
//   offset 16  the text header, H bytes of "key value\n" lines, in this order:
//                program_version 0.1.0
//                scene_hash 0123456789abcdef
//                samples FIRST NEXT TARGET
//                setting NAME VALUE          (one per image setting, image_settings()' order)
//                film WIDTH HEIGHT
//                adaptive_state yes|no       (whether the stopping block below is there)
//                channel NAME BYTES          (one per film channel: sum.R sum.G sum.B
//                                             square.R square.G square.B, then the extra
//                                             channels; BYTES is 8 or 16)
//   then       a record per pixel, rows top to bottom: its sample count (u32), then its sum
//              of each channel in order, a two's complement integer of BYTES bytes in units of
//              2^-40 (fixed_point.h). A channel whose sums all fit in 64 bits is stored in 8,
//              which halves the file of a typical render. Records in the film's own order make
//              writing and reading one pass over its memory.
//   then       with adaptive_state yes (an adaptive render, adaptive_state.h): a u32 per pixel,
//              rows top to bottom, the sample at which the pixel stopped (at most NEXT), or
//              4294967295 while it is still sampled. Such a render always starts at sample 0.
//   last       XXH3-64 of every byte before it, u64
//
// Version 2 added the adaptive_state line and block; version 1 files are refused, by name.
//
// The checksum is there to catch accidents (a truncated copy, a flipped bit, a file that is
// not ours), not tampering: a damaged file passes it with probability 2^-64, and the hash
// reads a gigabyte in about a tenth of a second. Nothing in a checkpoint runs or is trusted
// beyond its sizes, which are checked against the file before anything is allocated.

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace wt::checkpoint_format {

constexpr char magic[8] = {'\x89', 'W', 'T', 'C', 'K', 'P', 'T', '\n'};
constexpr uint32_t version = 2;
constexpr std::size_t preamble_bytes = 16;  // magic, version, header length
constexpr std::size_t checksum_bytes = 8;
constexpr uint32_t max_header_bytes = 1 << 16;
constexpr int max_film_side = 65536;  // the scene format's limit
constexpr const char* base_channels[6] = {"sum.R", "sum.G", "sum.B", "square.R", "square.G", "square.B"};

inline void put_u32(unsigned char* p, uint32_t v) {
    for (int i = 0; i < 4; ++i) p[i] = (unsigned char)(v >> (8 * i));
}
inline void put_u64(unsigned char* p, uint64_t v) {
    for (int i = 0; i < 8; ++i) p[i] = (unsigned char)(v >> (8 * i));
}
inline uint32_t get_u32(const unsigned char* p) {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= uint32_t(p[i]) << (8 * i);
    return v;
}
inline uint64_t get_u64(const unsigned char* p) {
    uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= uint64_t(p[i]) << (8 * i);
    return v;
}

}  // namespace wt::checkpoint_format
