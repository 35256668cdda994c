// Decoding a checkpoint (layout: checkpoint_format.h). Every claim the file makes about sizes
// is checked against its length before anything is allocated, and every message names the
// file, and the byte offset where there is one.

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cstring>
#include <memory>
#include <optional>

#include <xxhash.h>

#include "core/checkpoint/checkpoint.h"
#include "core/checkpoint/checkpoint_format.h"
#include "core/description/scene_hash.h"
#include "core/system/version.h"

namespace wt {

namespace fmt = checkpoint_format;

namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what) { throw CheckpointError(name + ": " + what); }
[[noreturn]] void fail_at(const std::string& name, uint64_t offset, const std::string& what) {
    fail(name, "byte " + std::to_string(offset) + ": " + what);
}

struct ChannelLayout {
    std::string name;
    std::size_t bytes = 0;
};

struct ParsedHeader {
    CheckpointHeader header;
    int width = 0, height = 0;
    bool adaptive_state = false;  // the per-pixel stopping block follows the records
    std::vector<ChannelLayout> channels;
    uint64_t file_bytes = 0;  // what the whole file must measure
};

bool parse_u64(const std::string& s, uint64_t max, uint64_t& out) {
    if (s.empty() || s.size() > 20) return false;
    uint64_t v = 0;
    for (char c : s) {
        if (c < '0' || c > '9') return false;
        const uint64_t digit = uint64_t(c - '0');
        if (v > (max - digit) / 10) return false;
        v = v * 10 + digit;
    }
    out = v;
    return true;
}

bool parse_hex64(const std::string& s, uint64_t& out) {
    if (s.size() != 16) return false;
    uint64_t v = 0;
    for (char c : s) {
        const int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
        if (digit < 0) return false;
        v = (v << 4) | uint64_t(digit);
    }
    out = v;
    return true;
}

// The text header, a line at a time; each line's fields split on single spaces.
class HeaderLines {
public:
    HeaderLines(std::string_view text, uint64_t offset, const std::string& name) : text_(text), base_(offset), name_(name) {}

    bool at_end() const { return pos_ == text_.size(); }
    // The next line's fields, which must start with `key` and number `count` in all.
    std::vector<std::string> next(const char* key, std::size_t count, const char* form) {
        line_offset_ = base_ + pos_;
        const std::size_t end = text_.find('\n', pos_);
        if (end == std::string_view::npos) error(std::string("expected '") + form + "', got an unterminated line");
        const std::string_view line = text_.substr(pos_, end - pos_);
        std::vector<std::string> fields;
        for (std::size_t start = 0;;) {
            const std::size_t space = line.find(' ', start);
            fields.emplace_back(line.substr(start, space == std::string_view::npos ? std::string_view::npos : space - start));
            if (space == std::string_view::npos) break;
            start = space + 1;
        }
        if (fields.size() != count || fields[0] != key)
            error(std::string("expected '") + form + "', got '" + printable(line) + "'");
        pos_ = end + 1;
        return fields;
    }
    bool next_is(const char* key) const {
        const std::size_t n = std::strlen(key);
        return text_.substr(pos_, n + 1) == std::string(key) + " ";
    }
    [[noreturn]] void error(const std::string& what) const { fail_at(name_, line_offset_, what); }

private:
    static std::string printable(std::string_view s) {
        std::string out;
        for (char c : s.substr(0, 80)) out += (c >= 32 && c < 127) ? c : '?';
        return out;
    }
    std::string_view text_;
    uint64_t base_;
    const std::string& name_;
    std::size_t pos_ = 0;
    uint64_t line_offset_ = 0;
};

uint32_t field_u32(HeaderLines& lines, const std::string& s, const char* what) {
    uint64_t v = 0;
    if (!parse_u64(s, UINT32_MAX, v)) lines.error(std::string(what) + " '" + s + "' is not an integer from 0 to 4294967295");
    return uint32_t(v);
}

// The preamble and the text header; `bytes` is known to hold at least the preamble and the header.
ParsedHeader parse_header(std::string_view bytes, uint32_t header_length, const std::string& name) {
    ParsedHeader p;
    HeaderLines lines(bytes.substr(fmt::preamble_bytes, header_length), fmt::preamble_bytes, name);
    CheckpointHeader& h = p.header;
    h.program_version = lines.next("program_version", 2, "program_version VERSION")[1];
    if (!parse_hex64(lines.next("scene_hash", 2, "scene_hash HEX")[1], h.scene_hash))
        lines.error("the scene hash must be 16 lowercase hex digits");
    const std::vector<std::string> samples = lines.next("samples", 4, "samples FIRST NEXT TARGET");
    h.first_sample = field_u32(lines, samples[1], "first sample");
    h.next_sample = field_u32(lines, samples[2], "next sample");
    h.target_sample = field_u32(lines, samples[3], "target sample");
    if (!(h.first_sample <= h.next_sample && h.next_sample <= h.target_sample))
        lines.error("the sample range " + samples[1] + " " + samples[2] + " " + samples[3] +
                    " is not FIRST <= NEXT <= TARGET");
    while (lines.next_is("setting")) {
        const std::vector<std::string> f = lines.next("setting", 3, "setting NAME VALUE");
        for (const NamedSetting& s : h.settings)
            if (s.name == f[1]) lines.error("setting '" + f[1] + "' given twice");
        h.settings.push_back({f[1], f[2]});
    }
    const std::vector<std::string> film = lines.next("film", 3, "film WIDTH HEIGHT");
    uint64_t w = 0, h_ = 0;
    if (!parse_u64(film[1], fmt::max_film_side, w) || !parse_u64(film[2], fmt::max_film_side, h_) || w == 0 || h_ == 0)
        lines.error("film size " + film[1] + "x" + film[2] + " is not two integers from 1 to 65536");
    p.width = int(w), p.height = int(h_);
    const std::string adaptive = lines.next("adaptive_state", 2, "adaptive_state yes|no")[1];
    if (adaptive != "yes" && adaptive != "no") lines.error("adaptive_state must be yes or no, got '" + adaptive + "'");
    p.adaptive_state = adaptive == "yes";
    if (p.adaptive_state && h.first_sample != 0)
        lines.error("an adaptive render's checkpoint starts at sample 0, this one at " + samples[1]);
    while (!lines.at_end()) {
        if (p.channels.size() == 6 + Film::max_extra_channels)
            lines.error("more than " + std::to_string(6 + Film::max_extra_channels) + " channels");
        const std::vector<std::string> f = lines.next("channel", 3, "channel NAME BYTES");
        const std::size_t index = p.channels.size();
        if (index < 6 && f[1] != fmt::base_channels[index])
            lines.error("channel " + std::to_string(index) + " must be " + fmt::base_channels[index] + ", got '" + f[1] + "'");
        if (f[2] != "8" && f[2] != "16") lines.error("channel '" + f[1] + "' has " + f[2] + " bytes per sum; 8 or 16 expected");
        p.channels.push_back({f[1], f[2] == "8" ? 8u : 16u});
    }
    if (p.channels.size() < 6) fail(name, "the header lists " + std::to_string(p.channels.size()) + " channels, at least 6 expected");

    const uint64_t pixels = w * h_;  // at most 2^32
    uint64_t per_pixel = 4;
    for (const ChannelLayout& c : p.channels) per_pixel += c.bytes;  // at most 4 + 22 * 16
    const uint64_t adaptive_block = p.adaptive_state ? pixels * 4 : 0;
    p.file_bytes = fmt::preamble_bytes + header_length + pixels * per_pixel + adaptive_block + fmt::checksum_bytes;
    return p;
}

std::optional<ParsedHeader> try_parse_header(std::string_view bytes, uint32_t header_length, const std::string& name) {
    try {
        return parse_header(bytes, header_length, name);
    } catch (const CheckpointError&) {
        return std::nullopt;
    }
}

std::string size_mismatch(uint64_t expected, uint64_t actual) {
    if (actual < expected)
        return "truncated: the header describes " + std::to_string(expected) + " bytes, the file has " + std::to_string(actual);
    return "the header describes " + std::to_string(expected) + " bytes, the file has " + std::to_string(actual) +
           " (data after the end)";
}

FixedPoint get_sum(const unsigned char* p, std::size_t bytes) {
    const uint64_t low = fmt::get_u64(p);
    if (bytes == 8) return FixedPoint(int64_t(low));
    return FixedPoint((unsigned __int128)fmt::get_u64(p + 8) << 64 | low);
}

// The stopping block (checkpoint_format.h): each pixel stopped at most at NEXT, and holds no
// more samples than it was given.
void read_adaptive_state(const unsigned char* block, const unsigned char* data, const ParsedHeader& p, Film& film,
                         const std::string& name) {
    AdaptiveState& state = film.adaptive();
    state.next_sample = p.header.next_sample;
    state.stopped_at.resize(film.pixel_total());
    for (std::size_t i = 0; i < state.stopped_at.size(); ++i, block += 4) {
        const uint32_t stop = fmt::get_u32(block);
        const std::string pixel =
            "pixel (" + std::to_string(i % std::size_t(p.width)) + ", " + std::to_string(i / std::size_t(p.width)) + ")";
        if (stop != AdaptiveState::still_sampling && stop > p.header.next_sample)
            fail_at(name, uint64_t(block - data),
                    pixel + " stopped at sample " + std::to_string(stop) + ", after the file's next sample " +
                        std::to_string(p.header.next_sample));
        state.stopped_at[i] = stop;
        if (film.pixel_count(uint32_t(i)) > state.samples_of(i))
            fail_at(name, uint64_t(block - data),
                    pixel + " has " + std::to_string(film.pixel_count(uint32_t(i))) + " samples but stopped at sample " +
                        std::to_string(stop));
    }
}

}  // namespace

namespace {
// A film of these channels, or the reason the file's channel list cannot be one as a CheckpointError.
Film film_with_channels(const std::string& name, int width, int height, const std::vector<std::string>& extra) {
    try {
        return Film(width, height, extra);
    } catch (const std::invalid_argument& e) {
        fail(name, e.what());
    }
}
}  // namespace

Checkpoint parse_checkpoint(std::string_view bytes, const std::string& name, bool verify_checksum) {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const uint64_t size = bytes.size();
    if (size >= sizeof fmt::magic && std::memcmp(data, fmt::magic, sizeof fmt::magic) != 0)
        fail(name, "not a wavetrace checkpoint (it does not start with the checkpoint signature)");
    if (size < fmt::preamble_bytes + fmt::checksum_bytes)
        fail(name, "truncated: " + std::to_string(size) + " bytes, a checkpoint has at least " +
                       std::to_string(fmt::preamble_bytes + fmt::checksum_bytes));
    const uint32_t version = fmt::get_u32(data + 8);
    if (version != fmt::version)
        fail_at(name, 8, "checkpoint format version " + std::to_string(version) + ", this program reads version " +
                             std::to_string(fmt::version) +
                             (version < fmt::version ? " (version 2 added adaptive sampling's per-pixel state): resume "
                                                       "or merge it with the wavetrace that wrote it"
                                                     : ""));
    const uint32_t header_length = fmt::get_u32(data + 12);
    if (header_length > fmt::max_header_bytes)
        fail_at(name, 12, "header length " + std::to_string(header_length) + " is more than the " +
                              std::to_string(fmt::max_header_bytes) + " a checkpoint header may have");
    if (fmt::preamble_bytes + header_length + fmt::checksum_bytes > size)
        fail(name, "truncated: the header alone needs " + std::to_string(fmt::preamble_bytes + header_length) +
                       " bytes and the checksum 8 more, the file has " + std::to_string(size));

    // The checksum first: a damaged file is reported as damaged, not by whatever it damaged.
    const uint64_t stored = fmt::get_u64(data + size - fmt::checksum_bytes);
    if (verify_checksum && XXH3_64bits(data, size - fmt::checksum_bytes) != stored) {
        const std::optional<ParsedHeader> p = try_parse_header(bytes, header_length, name);
        if (p && p->file_bytes != size) fail(name, size_mismatch(p->file_bytes, size));
        fail(name, "checksum mismatch: the file is damaged (corrupted, or cut short and padded)");
    }
    ParsedHeader p = parse_header(bytes, header_length, name);
    if (p.header.program_version != program_version())
        fail(name, "written by wavetrace " + p.header.program_version + ", this is wavetrace " + program_version() +
                       ", which may render the scene differently: resume or merge it with version " +
                       p.header.program_version);
    if (p.file_bytes != size) fail(name, size_mismatch(p.file_bytes, size));

    // Sizes are now known to match the bytes there, so the film is at most twice the file.
    std::vector<std::string> extra;
    for (std::size_t c = 6; c < p.channels.size(); ++c) extra.push_back(p.channels[c].name);
    Checkpoint checkpoint{p.header, film_with_channels(name, p.width, p.height, extra)};
    Film& film = checkpoint.film;
    const uint32_t range = p.header.next_sample - p.header.first_sample;
    // Every sample of the range traced its light paths, whatever the pixels' counts.
    if (film.has_splats()) film.set_splat_samples(range);
    const unsigned char* record = data + fmt::preamble_bytes + header_length;
    std::vector<uint32_t>& counts = film.raw_counts();
    FixedPoint* sums = film.raw_sums().data();
    const std::size_t stride = p.channels.size();
    for (std::size_t i = 0; i < counts.size(); ++i, sums += stride) {
        counts[i] = fmt::get_u32(record);
        if (counts[i] > range)
            fail_at(name, uint64_t(record - data),
                    "pixel (" + std::to_string(i % std::size_t(p.width)) + ", " + std::to_string(i / std::size_t(p.width)) +
                        ") has " + std::to_string(counts[i]) + " samples, more than the " + std::to_string(range) +
                        " of the file's sample range");
        record += 4;
        for (std::size_t c = 0; c < stride; ++c) {
            sums[c] = get_sum(record, p.channels[c].bytes);
            record += p.channels[c].bytes;
        }
    }
    if (p.adaptive_state) read_adaptive_state(record, data, p, film, name);
    return checkpoint;
}

Checkpoint read_checkpoint_file(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) fail(path, std::string("cannot open: ") + std::strerror(errno));
    // Not a std::string: its resize would write zeros over a gigabyte only to read over them.
    std::unique_ptr<char[]> bytes;
    std::size_t done = 0;
    try {
        struct stat st;
        if (::fstat(fd, &st) != 0) fail(path, std::string("cannot read: ") + std::strerror(errno));
        if (!S_ISREG(st.st_mode)) fail(path, "not a regular file");
        const std::size_t size = std::size_t(st.st_size);
        bytes.reset(new char[std::max<std::size_t>(size, 1)]);
        while (done < size) {
            const ssize_t got = ::read(fd, bytes.get() + done, size - done);
            if (got < 0 && errno == EINTR) continue;
            if (got < 0) fail(path, std::string("cannot read: ") + std::strerror(errno));
            if (got == 0) break;  // shrank while being read: parsed as the truncated file it now is
            done += std::size_t(got);
        }
    } catch (...) {
        ::close(fd);
        throw;
    }
    ::close(fd);
    return parse_checkpoint(std::string_view(bytes.get(), done), path);
}

}  // namespace wt
