#pragma once
// The instruction sets the kernels are compiled for, and their names: header-only, so the
// command-line code can offer and parse them without linking the kernels.

#include <cstdint>
#include <optional>
#include <string>

namespace wt {

enum class Isa : uint8_t { scalar, sse4, avx2, avx512 };
// Every ISA, narrowest first: what parsing, the command lines and the tests iterate over.
inline constexpr Isa kAllIsas[] = {Isa::scalar, Isa::sse4, Isa::avx2, Isa::avx512};

inline const char* isa_name(Isa isa) {
    switch (isa) {
        case Isa::scalar: return "scalar";
        case Isa::sse4: return "sse4";
        case Isa::avx2: return "avx2";
        case Isa::avx512: return "avx512";
    }
    return "unknown";
}

// isa_name of one of kAllIsas; empty for anything else ("auto" is the caller's business).
inline std::optional<Isa> parse_isa(const std::string& name) {
    for (Isa isa : kAllIsas)
        if (name == isa_name(isa)) return isa;
    return std::nullopt;
}

// The names of kAllIsas, in order, joined by `separator`: for help texts and errors.
inline std::string isa_names(const std::string& separator) {
    std::string names;
    for (Isa isa : kAllIsas) names += (names.empty() ? "" : separator) + isa_name(isa);
    return names;
}

}  // namespace wt
