#pragma once
// Strict checks of numeric command-line values, stricter than CLI11's own conversion: it reads
// integers with base 0 (so `--spp 0x10` is 16 and `--spp 010` is 8) and unsigned ones through
// strtoull (so `--seed -1` and `--seed 18446744073709551616` both become 2^64 - 1). The scene
// file refuses all of these; the command line must agree with it.

#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace wt {

// The value of a decimal integer of digits only (no sign, no prefix, no spaces), if it is one
// and fits 64 bits; leading zeros are allowed and mean nothing.
std::optional<uint64_t> parse_decimal(const std::string& text);

// A CLI11 transform (register it with ->transform(), not ->check(), which may not rewrite): a decimal integer in [lo, hi]. It rewrites the text without leading
// zeros, so CLI11's own base-0 conversion afterwards reads the same number. Its message shows
// the value with non-printable bytes escaped.
CLI::Validator decimal_integer(uint64_t lo, uint64_t hi);

// A CLI11 check: a finite number >= 0 that fits a 32-bit float, as the scene file reads one
// (CLI11's NonNegativeNumber lets "inf" and "nan" through).
CLI::Validator non_negative_float();

// A CLI11 failure message with the error's non-printable bytes escaped.
std::string printable_failure_message(const CLI::App* app, const CLI::Error& e);

}  // namespace wt
