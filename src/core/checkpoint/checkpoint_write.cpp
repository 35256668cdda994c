// Encoding a checkpoint (layout: checkpoint_format.h), streamed through one buffer so a
// gigabyte film is never copied whole.

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <sstream>

#include <xxhash.h>

#include "core/system/atomic_file.h"
#include "core/checkpoint/checkpoint.h"
#include "core/checkpoint/checkpoint_format.h"
#include "core/description/scene_hash.h"

namespace wt {

namespace fmt = checkpoint_format;

namespace {

// Collects bytes into a buffer, hashes them, and hands full buffers to `flush`.
class ChecksummedSink {
public:
    explicit ChecksummedSink(std::function<void(const unsigned char*, std::size_t)> flush)
        : flush_(std::move(flush)), buffer_(1 << 20), state_(XXH3_createState()) {
        if (!state_) throw std::bad_alloc();
        XXH3_64bits_reset(state_);
    }
    ~ChecksummedSink() { XXH3_freeState(state_); }
    ChecksummedSink(const ChecksummedSink&) = delete;
    ChecksummedSink& operator=(const ChecksummedSink&) = delete;

    // Room for `n` (at most a pixel's record, 4 + 22 * 16 bytes) contiguous bytes, to be filled by the caller.
    unsigned char* reserve(std::size_t n) {
        if (used_ + n > buffer_.size()) drain();
        unsigned char* p = buffer_.data() + used_;
        used_ += n;
        return p;
    }
    void bytes(const void* data, std::size_t n) {
        const unsigned char* p = static_cast<const unsigned char*>(data);
        while (n > 0) {
            if (used_ == buffer_.size()) drain();
            const std::size_t step = std::min(n, buffer_.size() - used_);
            std::memcpy(buffer_.data() + used_, p, step);
            used_ += step, p += step, n -= step;
        }
    }
    // Appends the checksum of everything so far, unhashed, and flushes.
    void finish() {
        drain();
        unsigned char sum[fmt::checksum_bytes];
        fmt::put_u64(sum, XXH3_64bits_digest(state_));
        flush_(sum, sizeof sum);
    }

private:
    void drain() {
        XXH3_64bits_update(state_, buffer_.data(), used_);
        flush_(buffer_.data(), used_);
        used_ = 0;
    }

    std::function<void(const unsigned char*, std::size_t)> flush_;
    std::vector<unsigned char> buffer_;
    std::size_t used_ = 0;
    XXH3_state_t* state_;
};

bool is_token(const std::string& s) {
    if (s.empty()) return false;
    for (char c : s)
        if (c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\0') return false;
    return true;
}

// Per channel, 8 bytes when every sum of the channel fits in 64 bits, else 16: one pass over
// the film in memory order.
std::vector<std::size_t> channel_bytes(const Film& film) {
    const auto& sums = film.raw_sums();
    const std::size_t stride = film.channels_per_pixel();
    const FixedPoint lo = std::numeric_limits<int64_t>::min(), hi = std::numeric_limits<int64_t>::max();
    std::vector<bool> wide(stride, false);
    for (std::size_t i = 0; i < sums.size(); i += stride)
        for (std::size_t c = 0; c < stride; ++c)
            if (sums[i + c] < lo || sums[i + c] > hi) wide[c] = true;
    std::vector<std::size_t> bytes(stride);
    for (std::size_t c = 0; c < stride; ++c) bytes[c] = wide[c] ? 16 : 8;
    return bytes;
}

std::string header_text(const CheckpointHeader& h, const Film& film, const std::vector<std::size_t>& widths) {
    if (!(h.first_sample <= h.next_sample && h.next_sample <= h.target_sample))
        throw std::invalid_argument("checkpoint: sample range out of order");
    if (!is_token(h.program_version)) throw std::invalid_argument("checkpoint: bad program version");
    std::ostringstream text;
    text << "program_version " << h.program_version << "\n";
    text << "scene_hash " << hash_to_hex(h.scene_hash) << "\n";
    text << "samples " << h.first_sample << " " << h.next_sample << " " << h.target_sample << "\n";
    for (const NamedSetting& s : h.settings) {
        if (!is_token(s.name) || !is_token(s.value))
            throw std::invalid_argument("checkpoint: setting '" + s.name + "' cannot be stored");
        text << "setting " << s.name << " " << s.value << "\n";
    }
    text << "film " << film.width() << " " << film.height() << "\n";
    const AdaptiveState& adaptive = film.adaptive();
    if (!adaptive.empty() && (h.first_sample != 0 || adaptive.next_sample != h.next_sample))
        throw std::invalid_argument("checkpoint: the film's adaptive state is of samples 0:" +
                                    std::to_string(adaptive.next_sample) + ", the header says " +
                                    std::to_string(h.first_sample) + ":" + std::to_string(h.next_sample));
    text << "adaptive_state " << (adaptive.empty() ? "no" : "yes") << "\n";
    for (std::size_t c = 0; c < film.channels_per_pixel(); ++c) {
        const std::string name = c < 6 ? fmt::base_channels[c] : film.extra_channels()[c - 6];
        if (!is_token(name)) throw std::invalid_argument("checkpoint: channel '" + name + "' cannot be stored");
        text << "channel " << name << " " << widths[c] << "\n";
    }
    if (text.str().size() > fmt::max_header_bytes) throw std::invalid_argument("checkpoint: header too long");
    return text.str();
}

void encode(const CheckpointHeader& h, const Film& film, ChecksummedSink& out) {
    const std::size_t channels = film.channels_per_pixel();
    const std::vector<std::size_t> widths = channel_bytes(film);
    std::size_t pixel_bytes = 4;
    for (std::size_t w : widths) pixel_bytes += w;
    const std::string text = header_text(h, film, widths);

    unsigned char* pre = out.reserve(fmt::preamble_bytes);
    std::memcpy(pre, fmt::magic, sizeof fmt::magic);
    fmt::put_u32(pre + 8, fmt::version);
    fmt::put_u32(pre + 12, uint32_t(text.size()));
    out.bytes(text.data(), text.size());

    const std::vector<uint32_t>& counts = film.raw_counts();
    const FixedPoint* sums = film.raw_sums().data();
    for (std::size_t pixel = 0; pixel < counts.size(); ++pixel, sums += channels) {
        unsigned char* p = out.reserve(pixel_bytes);
        fmt::put_u32(p, counts[pixel]);
        p += 4;
        for (std::size_t c = 0; c < channels; ++c) {
            const unsigned __int128 v = (unsigned __int128)sums[c];  // two's complement bits
            fmt::put_u64(p, uint64_t(v));
            if (widths[c] == 16) fmt::put_u64(p + 8, uint64_t(v >> 64));
            p += widths[c];
        }
    }
    for (const uint32_t stop : film.adaptive().stopped_at) fmt::put_u32(out.reserve(4), stop);
    out.finish();
}

void write_all(int fd, const unsigned char* data, std::size_t n, const std::string& path) {
    while (n > 0) {
        const ssize_t written = ::write(fd, data, n);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) throw FileWriteError(path + ": cannot write: " + std::strerror(written < 0 ? errno : ENOSPC));
        data += written, n -= std::size_t(written);
    }
}

}  // namespace

std::string checkpoint_bytes(const CheckpointHeader& header, const Film& film) {
    std::string bytes;
    ChecksummedSink sink([&](const unsigned char* p, std::size_t n) { bytes.append(reinterpret_cast<const char*>(p), n); });
    encode(header, film, sink);
    return bytes;
}

void write_checkpoint_file(const std::string& path, const CheckpointHeader& header, const Film& film) {
    write_file_atomically(path, [&](const std::string& temporary) {
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (fd < 0) throw FileWriteError(path + ": cannot create " + temporary + ": " + std::strerror(errno));
        try {
            ChecksummedSink sink([&](const unsigned char* p, std::size_t n) { write_all(fd, p, n, path); });
            encode(header, film, sink);
        } catch (...) {
            ::close(fd);
            throw;
        }
        if (::close(fd) != 0) throw FileWriteError(path + ": cannot write: " + std::strerror(errno));
    });
}

bool is_checkpoint_path(const std::string& path) { return std::filesystem::path(path).extension() == ".ckpt"; }

}  // namespace wt
