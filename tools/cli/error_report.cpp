#include "tools/cli/error_report.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace wt {

namespace {

const char* channel_name(int c) { return c == 0 ? "R" : c == 1 ? "G" : "B"; }

std::string worst_pixel(const ErrorMetrics& m) {
    std::ostringstream s;
    s << std::setprecision(4) << m.max_error << " at (" << m.max_x << "," << m.max_y << ") " << channel_name(m.max_channel);
    return s.str();
}

std::string number(double v, int precision) {
    if (std::isnan(v)) return "n/a";
    std::ostringstream s;
    s << std::setprecision(precision) << v;
    return s.str();
}

}  // namespace

void print_error_table(std::ostream& out, const ImageErrorReport& report) {
    const auto row = [&](const std::string& name, const ErrorMetrics& m) {
        out << std::left << std::setw(9) << name << std::setw(13) << number(m.rmse, 6) << std::setw(13)
            << number(m.rel_mse, 6) << std::setw(11) << number(m.psnr, 4) << std::setw(12) << number(m.mean_ratio, 6)
            << worst_pixel(m) << "\n";
    };
    out << std::left << std::setw(9) << "channel" << std::setw(13) << "RMSE" << std::setw(13) << "relMSE" << std::setw(11)
        << "PSNR(dB)" << std::setw(12) << "mean_ratio" << "worst_pixel\n";
    for (int c = 0; c < 3; ++c) row(channel_name(c), report.channel[std::size_t(c)]);
    row("overall", report.overall);
}

std::string error_summary(const ErrorMetrics& m) {
    return "RMSE " + number(m.rmse, 5) + ", relMSE " + number(m.rel_mse, 5) + ", PSNR " + number(m.psnr, 4) +
           " dB, mean ratio " + number(m.mean_ratio, 5) + ", worst " + worst_pixel(m);
}

}  // namespace wt
