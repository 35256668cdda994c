#pragma once
// How the commands print an ImageErrorReport: a table per channel (compare) or one line (render).

#include <ostream>
#include <string>

#include "core/image_metrics/image_metrics.h"

namespace wt {

// Columns: channel, RMSE, relMSE, PSNR, mean ratio, worst pixel; the rows R, G, B, overall. The
// first three columns of the `overall` row are what scripts read (tools/make_reference.sh).
void print_error_table(std::ostream& out, const ImageErrorReport& report);

// "RMSE 0.0123, relMSE 0.00456, PSNR 38.2 dB, mean ratio 1.0021, worst 0.53 at (12,40) G"
std::string error_summary(const ErrorMetrics& overall);

}  // namespace wt
