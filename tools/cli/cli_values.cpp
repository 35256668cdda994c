#include "tools/cli/cli_values.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/base/printable.h"

namespace wt {

std::optional<uint64_t> parse_decimal(const std::string& text) {
    if (text.empty()) return std::nullopt;
    uint64_t value = 0;
    for (const char c : text) {
        if (c < '0' || c > '9') return std::nullopt;
        const uint64_t digit = uint64_t(c - '0');
        if (value > (UINT64_MAX - digit) / 10) return std::nullopt;  // would wrap
        value = value * 10 + digit;
    }
    return value;
}

CLI::Validator decimal_integer(uint64_t lo, uint64_t hi) {
    const std::string range = "a decimal integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    return CLI::Validator(
        [lo, hi, range](std::string& text) -> std::string {
            const std::optional<uint64_t> value = parse_decimal(text);
            if (!value || *value < lo || *value > hi) return "expected " + range + ", got '" + printable(text) + "'";
            text = std::to_string(*value);
            return {};
        },
        range);
}

CLI::Validator non_negative_float() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            const std::string expected = "expected a finite number >= 0, got '" + printable(text) + "'";
            // Decimal notation only, as JSON writes numbers: no hex floats, no "inf" or "nan".
            if (text.empty() || text.find_first_not_of("0123456789.eE+-") != std::string::npos) return expected;
            char* end = nullptr;
            errno = 0;
            const double value = std::strtod(text.c_str(), &end);
            if (*end != '\0' || errno == ERANGE || !std::isfinite(value) || !(value >= 0.0) ||
                !std::isfinite(float(value)))
                return expected;
            return {};
        },
        "NUMBER >= 0");
}

std::string printable_failure_message(const CLI::App* app, const CLI::Error& e) {
    std::string message = printable(e.what()) + "\n";
    if (app->get_help_ptr() != nullptr)
        message += "Run with " + app->get_help_ptr()->get_name() + " for more information.\n";
    return message;
}

}  // namespace wt
