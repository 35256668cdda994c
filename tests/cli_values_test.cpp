// The command line's numbers, as the scene file reads them: decimal digits, no wrap-around.

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include "tools/cli/cli_values.h"

namespace {

TEST(CliValues, DecimalDigitsOnly) {
    EXPECT_EQ(wt::parse_decimal("0"), 0u);
    EXPECT_EQ(wt::parse_decimal("010"), 10u);  // not octal
    EXPECT_EQ(wt::parse_decimal("18446744073709551615"), UINT64_MAX);
    for (const char* bad : {"", "0x10", "-1", "+5", " 5", "5 ", "1e3", "18446744073709551616", "99999999999999999999", "\xff"})
        EXPECT_FALSE(wt::parse_decimal(bad).has_value()) << bad;
}

// Parses `--n VALUE` through CLI11 with the transform, as render_command.cpp registers it.
template <typename T>
std::string parse(const std::string& value, T& out, uint64_t lo, uint64_t hi) {
    CLI::App app;
    app.add_option("--n", out)->transform(wt::decimal_integer(lo, hi));
    try {
        app.parse(std::vector<std::string>{value, "--n"});  // CLI11 takes the vector reversed
        return {};
    } catch (const CLI::ParseError& e) {
        return e.what();
    }
}

TEST(CliValues, CliElevenReadsTheNumberTheTransformAccepted) {
    int spp = 0;
    EXPECT_EQ(parse("010", spp, 1, 1 << 20), "");
    EXPECT_EQ(spp, 10);  // CLI11 alone reads 010 as octal 8
    EXPECT_EQ(parse("08", spp, 1, 1 << 20), "");  // and 08 as an error
    EXPECT_EQ(spp, 8);
    EXPECT_NE(parse("0x10", spp, 1, 1 << 20).find("expected a decimal integer in [1, 1048576], got '0x10'"), std::string::npos);
    uint64_t seed = 7;
    EXPECT_NE(parse("-1", seed, 0, UINT64_MAX).find("got '-1'"), std::string::npos);
    EXPECT_NE(parse("18446744073709551616", seed, 0, UINT64_MAX).find("got '18446744073709551616'"), std::string::npos);
    EXPECT_EQ(seed, 7u);
    EXPECT_EQ(parse("18446744073709551615", seed, 0, UINT64_MAX), "");
    EXPECT_EQ(seed, UINT64_MAX);
    EXPECT_NE(parse("\xff\x1b[31m", spp, 1, 10).find("got '\\xff\\x1b[31m'"), std::string::npos);
}

TEST(CliValues, NonNegativeFloatIsFiniteAndDecimal) {
    const auto check = [](std::string text) {
        CLI::App app;
        float value = -1.0f;
        app.add_option("--x", value)->check(wt::non_negative_float());
        try {
            app.parse(std::vector<std::string>{text, "--x"});
            return std::to_string(value);
        } catch (const CLI::ParseError& e) {
            return std::string(e.what());
        }
    };
    EXPECT_EQ(check("0"), std::to_string(0.0f));
    EXPECT_EQ(check("0.05"), std::to_string(0.05f));
    EXPECT_EQ(check("1e-3"), std::to_string(1e-3f));
    for (const char* bad : {"-0.1", "inf", "nan", "infinity", "0x1p3", "1e39", "", " 1", "1 ", "lots"})
        EXPECT_NE(check(bad).find("expected a finite number >= 0"), std::string::npos) << bad;
}

}  // namespace
