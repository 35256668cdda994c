#pragma once
// `wavetrace render --reference REF [--error-csv FILE]`: the render's error against a reference,
// printed and logged as CSV rows (seconds, spp, rmse, rel_mse), one per measurement.

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/film/film.h"
#include "core/film/image_error.h"
#include "core/film/rgb_image.h"

namespace wt {

struct ReferenceErrorOptions {
    std::optional<std::string> reference_path, csv_path;
};

void add_reference_error_options(CLI::App& render_command, ReferenceErrorOptions& options);

class ReferenceErrorLog {
public:
    // Reads and checks everything before rendering: the reference exists, is an image of the
    // render's size, and the CSV's directory is writable; --error-csv needs --reference.
    // Throws std::runtime_error naming the file. Inactive (records nothing) without --reference.
    ReferenceErrorLog(const ReferenceErrorOptions& options, int width, int height);

    bool active() const { return !reference_.rgb.empty(); }

    // The film's mean so far against the reference, remembered as one CSV row.
    ErrorMetrics record(double seconds, int spp, const Film& film);

    // Writes the CSV (if asked for), whole or not at all.
    void finish() const;

    const std::optional<std::string>& csv_path() const { return options_.csv_path; }

private:
    struct Row {
        double seconds;
        int spp;
        ErrorMetrics error;
    };
    ReferenceErrorOptions options_;
    RgbImage reference_;
    std::vector<Row> rows_;
};

}  // namespace wt
