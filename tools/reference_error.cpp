#include "reference_error.h"

#include <chrono>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/film/image_input.h"

namespace wt {

void add_reference_error_options(CLI::App& cmd, ReferenceErrorOptions& o) {
    cmd.add_option("--reference", o.reference_path,
                   "Reference image (linear EXR) of the render's size: print the error against it at each pass");
    cmd.add_option("--error-csv", o.csv_path, "With --reference: write seconds,spp,rmse,rel_mse rows (one per pass) to this CSV file");
}

ReferenceErrorLog::ReferenceErrorLog(const ReferenceErrorOptions& options, int width, int height, std::ostream* progress)
    : options_(options), progress_(progress) {
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

ErrorMetrics ReferenceErrorLog::record(double seconds, int spp, const Film& film) {
    RgbImage image{film.width(), film.height(), film.resolve()};
    const ErrorMetrics error = image_error(image, reference_).overall;
    rows_.push_back({seconds, spp, error});
    return error;
}

bool ReferenceErrorLog::pass_done(const Film& film, const PassReport& report) {
    const auto start = std::chrono::steady_clock::now();
    const double seconds = report.seconds - measuring_seconds_;
    const ErrorMetrics e = record(seconds, int(report.film_spp), film);
    if (progress_)
        *progress_ << "  pass " << std::left << std::setw(11) << report.pass << std::right << std::setw(6) << report.film_spp
                   << " spp " << std::fixed << std::setprecision(3) << std::setw(8) << seconds << " s  RMSE "
                   << std::defaultfloat << std::setprecision(5) << e.rmse << ", relMSE " << e.rel_mse << "\n";
    measuring_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return true;
}

std::optional<ErrorMetrics> ReferenceErrorLog::last() const {
    return rows_.empty() ? std::nullopt : std::optional(rows_.back().error);
}

void ReferenceErrorLog::finish() const {
    if (!options_.csv_path) return;
    std::ostringstream csv;
    csv.precision(9);
    csv << "seconds,spp,rmse,rel_mse\n";
    for (const Row& r : rows_) csv << r.seconds << "," << r.spp << "," << r.error.rmse << "," << r.error.rel_mse << "\n";
    write_text_file_atomically(*options_.csv_path, csv.str());
}

RenderResult render_measuring_error(const Scene& scene, const RenderOptions& options, Film& film, ReferenceErrorLog& log) {
    RenderSession session(scene, options);
    ProgressiveOptions passes;
    passes.samples = {0, uint32_t(scene.settings.spp)};
    render_progressive(session, film, passes, &log);
    return session.result();
}

}  // namespace wt
