#include "reference_error.h"

#include <sstream>
#include <stdexcept>

#include "atomic_text_file.h"
#include "core/film/image_input.h"

namespace wt {

void add_reference_error_options(CLI::App& cmd, ReferenceErrorOptions& o) {
    cmd.add_option("--reference", o.reference_path,
                   "Reference image (linear EXR) of the render's size: print the error against it at the end");
    cmd.add_option("--error-csv", o.csv_path, "With --reference: write seconds,spp,rmse,rel_mse rows to this CSV file");
}

ReferenceErrorLog::ReferenceErrorLog(const ReferenceErrorOptions& options, int width, int height) : options_(options) {
    if (!options.reference_path) {
        if (options.csv_path) throw std::runtime_error("--error-csv " + *options.csv_path + ": needs --reference");
        return;
    }
    if (options.csv_path) check_text_output_path(*options.csv_path);
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

void ReferenceErrorLog::finish() const {
    if (!options_.csv_path) return;
    std::ostringstream csv;
    csv.precision(9);
    csv << "seconds,spp,rmse,rel_mse\n";
    for (const Row& r : rows_) csv << r.seconds << "," << r.spp << "," << r.error.rmse << "," << r.error.rel_mse << "\n";
    write_text_file_atomically(*options_.csv_path, csv.str());
}

}  // namespace wt
