#pragma once
// `wavetrace render --reference REF [--error-csv FILE]`: the render's error against a reference
// at each progressive pass and at the end, printed and logged as CSV rows (seconds, spp, rmse,
// rel_mse), one per pass.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/film/film.h"
#include "core/film/image_error.h"
#include "core/film/rgb_image.h"
#include "kernels/progressive_render.h"
#include "kernels/renderer.h"

namespace wt {

struct ReferenceErrorOptions {
    std::optional<std::string> reference_path, csv_path;
};

void add_reference_error_options(CLI::App& render_command, ReferenceErrorOptions& options);

class ReferenceErrorLog : public PassObserver {
public:
    // Reads and checks everything before rendering: the reference exists, is an image of the
    // render's size, and the CSV's directory is writable; --error-csv needs --reference.
    // Throws naming the file. Inactive (records nothing) without --reference. Each pass's
    // error is printed to `progress` when it is given.
    ReferenceErrorLog(const ReferenceErrorOptions& options, int width, int height, std::ostream* progress);

    bool active() const { return !reference_.rgb.empty(); }

    // The film's mean so far against the reference, remembered as one CSV row.
    ErrorMetrics record(double seconds, int spp, const Film& film);

    // At a pass boundary: records the pass, its seconds those of rendering only (the time the
    // error measurements took is taken out).
    bool pass_done(const Film& film, const PassReport& report) override;

    // The last error recorded, if any.
    std::optional<ErrorMetrics> last() const;

    // Writes the CSV (if asked for), whole or not at all.
    void finish() const;

private:
    struct Row {
        double seconds;
        int spp;
        ErrorMetrics error;
    };
    ReferenceErrorOptions options_;
    RgbImage reference_;
    std::ostream* progress_;
    std::vector<Row> rows_;
    double measuring_seconds_ = 0.0;
};

// All of the scene's samples in progressive passes (kernels/progressive_render.h), the error
// taken at each pass boundary: the same film, bit for bit, as render() makes.
RenderResult render_measuring_error(const Scene& scene, const RenderOptions& options, Film& film, ReferenceErrorLog& log);

}  // namespace wt
