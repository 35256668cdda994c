#pragma once
// `wavetrace render --reference REF [--error-csv FILE]`: the render's error against a reference
// at each progressive pass and at the end, printed and logged as CSV rows (seconds, spp, rmse,
// rel_mse), one per pass.

#include <ostream>
#include <vector>

#include "core/film/film.h"
#include "core/image_io/rgb_image.h"
#include "core/image_metrics/image_metrics.h"
#include "kernels/renderer.h"
#include "tools/render/reference_error_options.h"
#include "tools/render/render_passes.h"

namespace wt {

class ReferenceErrorLog {
public:
    // Reads and checks everything before rendering: the reference exists, is an image of the
    // render's size, and the CSV's directory is writable; --error-csv needs --reference.
    // Throws naming the file. Inactive (does nothing) without --reference.
    ReferenceErrorLog(const ReferenceErrorOptions& options, int width, int height);

    bool active() const { return !reference_.rgb.empty(); }

    // Measures the error at every pass boundary but the last, printing a line per pass to
    // `progress` if given. Its seconds are the session's rendering time, so neither the
    // measurements nor anything else done between passes count.
    void attach(RenderPassHooks& hooks, const RenderSession& session, std::ostream* progress);

    // The final film: records its row, writes the CSV (whole or not at all) and prints the error
    // line of the summary to `summary` if given.
    void finish(double seconds, uint32_t spp, const Film& film, std::ostream* summary);

    // The film's mean against the reference, remembered as one CSV row.
    ErrorMetrics record(double seconds, uint32_t spp, const Film& film);

private:
    struct Row {
        double seconds;
        uint32_t spp;
        ErrorMetrics error;
    };
    ReferenceErrorOptions options_;
    RgbImage reference_;
    std::vector<Row> rows_;
};

}  // namespace wt
