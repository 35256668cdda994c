#include "tools/render/reference_error.h"

#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "core/system/atomic_file.h"
#include "core/image_io/rgb_image_input.h"
#include "tools/cli/error_report.h"

namespace wt {

ReferenceErrorLog::ReferenceErrorLog(const ReferenceErrorOptions& options, int width, int height) : options_(options) {
    if (!options.reference_path) {
        if (options.csv_path) throw std::runtime_error("--error-csv " + *options.csv_path + ": needs --reference");
        return;
    }
    if (options.csv_path) check_output_directory(*options.csv_path);
    reference_ = read_rgb_image(*options.reference_path);
    if (reference_.width != width || reference_.height != height)
        throw std::runtime_error("--reference " + *options.reference_path + ": the reference is " +
                                 std::to_string(reference_.width) + "x" + std::to_string(reference_.height) +
                                 " but the render is " + std::to_string(width) + "x" + std::to_string(height));
}

ErrorMetrics ReferenceErrorLog::record(double seconds, uint32_t spp, const Film& film) {
    const ErrorMetrics error = image_error({film.width(), film.height(), film.resolve()}, reference_).overall;
    rows_.push_back({seconds, spp, error});
    return error;
}

void ReferenceErrorLog::attach(RenderPassHooks& hooks, const RenderSession& session, std::ostream* progress) {
    if (!active()) return;
    hooks.every(0.0, [this, &session, progress](const Film& film, const PassReport& report) {
        const double seconds = session.result().seconds;
        const ErrorMetrics e = record(seconds, report.film_spp, film);
        if (progress)
            *progress << "wavetrace: pass " << report.pass << ": " << report.film_spp << " spp, " << std::fixed
                      << std::setprecision(3) << seconds << " s, RMSE " << std::defaultfloat << std::setprecision(5)
                      << e.rmse << ", relMSE " << e.rel_mse << "\n";
    });
}

void ReferenceErrorLog::finish(double seconds, uint32_t spp, const Film& film, std::ostream* summary) {
    if (!active()) return;
    const ErrorMetrics e = record(seconds, spp, film);
    if (options_.csv_path) {
        std::ostringstream csv;
        csv.precision(9);
        csv << "seconds,spp,rmse,rel_mse\n";
        for (const Row& r : rows_) csv << r.seconds << "," << r.spp << "," << r.error.rmse << "," << r.error.rel_mse << "\n";
        write_text_file_atomically(*options_.csv_path, csv.str());
    }
    if (summary) {
        *summary << "  error            " << error_summary(e) << " (against " << *options_.reference_path << ")\n";
        if (options_.csv_path) *summary << "  wrote            " << *options_.csv_path << "\n";
    }
}

}  // namespace wt
