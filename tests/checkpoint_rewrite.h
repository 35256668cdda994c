#pragma once
// A checkpoint's bytes with a piece of its text header rewritten and the checksum made valid
// again (checkpoint_format.h has the layout). The tests use it to build what a writer with a bug
// or a hostile file could produce, past the checksum; the checkpoint fuzz target and the test of
// its seeds use it to give the committed seeds this program's version. The reader refuses any
// other version before it decodes the film, so without the rewrite every version bump would
// leave the fuzzer at that one refusal.

#include <string>
#include <string_view>

#include <xxhash.h>

#include "core/checkpoint/checkpoint_format.h"
#include "core/system/version.h"

namespace wt::test {

// `bytes` with the first `from` in the text header replaced by `to`, or unchanged when the
// bytes are too short to hold the header they claim or it has no `from`.
inline std::string with_header_text(std::string_view bytes, std::string_view from, std::string_view to) {
    namespace fmt = checkpoint_format;
    if (bytes.size() < fmt::preamble_bytes + fmt::checksum_bytes) return std::string(bytes);
    const uint32_t length = fmt::get_u32(reinterpret_cast<const unsigned char*>(bytes.data()) + 12);
    if (length > bytes.size() - fmt::preamble_bytes - fmt::checksum_bytes) return std::string(bytes);
    std::string text(bytes.substr(fmt::preamble_bytes, length));
    const std::size_t at = text.find(from);
    if (at == std::string::npos) return std::string(bytes);
    text.replace(at, from.size(), to);
    std::string out(bytes.substr(0, 12));
    unsigned char word[8];
    fmt::put_u32(word, uint32_t(text.size()));
    out.append(reinterpret_cast<const char*>(word), 4);
    out += text;
    out += bytes.substr(fmt::preamble_bytes + length, bytes.size() - fmt::preamble_bytes - length - fmt::checksum_bytes);
    fmt::put_u64(word, XXH3_64bits(out.data(), out.size()));
    return out.append(reinterpret_cast<const char*>(word), 8);
}

// `bytes` as this program would have written them: the header's first line names its version.
// A file whose checksum did not match keeps a checksum that does not (the fuzz target's inputs
// with a damaged checksum stay damaged).
inline std::string with_this_program_version(std::string_view bytes) {
    namespace fmt = checkpoint_format;
    constexpr std::string_view key = "program_version ";
    if (bytes.size() < fmt::preamble_bytes + key.size() + fmt::checksum_bytes ||
        bytes.substr(fmt::preamble_bytes, key.size()) != key)
        return std::string(bytes);
    const std::string_view rest = bytes.substr(fmt::preamble_bytes + key.size());
    const std::string_view version = rest.substr(0, rest.find('\n'));
    if (version == program_version()) return std::string(bytes);
    const std::size_t body = bytes.size() - fmt::checksum_bytes;
    const bool sealed =
        XXH3_64bits(bytes.data(), body) == fmt::get_u64(reinterpret_cast<const unsigned char*>(bytes.data()) + body);
    std::string out = with_header_text(bytes, std::string(key) + std::string(version) + "\n",
                                       std::string(key) + program_version() + "\n");
    if (!sealed) out.back() = char(out.back() ^ 1);
    return out;
}

}  // namespace wt::test
