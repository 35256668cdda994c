#include "tools/tradeoff/tradeoff_fit.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace wt {

ErrorFit fit_error_against_spp(const std::vector<SampledError>& points) {
    if (points.size() < 2) throw std::invalid_argument("fit_error_against_spp: needs at least two points");
    ErrorFit fit;
    fit.points = points.size();

    // Log-log line.
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (const SampledError& p : points) {
        if (!(p.spp > 0.0) || !(p.mse > 0.0)) throw std::invalid_argument("fit_error_against_spp: spp and errors must be positive");
        const double x = std::log(p.spp), y = 0.5 * std::log(p.mse);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double n = double(points.size());
    const double spread = sxx - sx * sx / n;
    if (!(spread > 0.0)) throw std::invalid_argument("fit_error_against_spp: needs two different spp");
    fit.slope = (sxy - sx * sy / n) / spread;
    fit.c = std::exp((sy - fit.slope * sx) / n);

    // floor + v / spp, least squares on (MSE_i - model) / MSE_i: a weighted linear fit in
    // (1, 1/spp) with weights 1 / MSE_i^2, solved by its 2x2 normal equations.
    double w = 0.0, wx = 0.0, wxx = 0.0, wy = 0.0, wxy = 0.0;
    for (const SampledError& p : points) {
        const double weight = 1.0 / (p.mse * p.mse), x = 1.0 / p.spp;
        w += weight, wx += weight * x, wxx += weight * x * x, wy += weight * p.mse, wxy += weight * x * p.mse;
    }
    const double det = w * wxx - wx * wx;
    fit.floor = (wy * wxx - wx * wxy) / det;
    fit.variance = (w * wxy - wx * wy) / det;
    if (fit.floor < 0.0) {  // no measurable floor: the pure 1/spp model
        fit.floor = 0.0;
        fit.variance = wxy / wxx;
    }
    return fit;
}

double spp_to_reach(const ErrorFit& fit, double target_rmse) {
    const double target = target_rmse * target_rmse;
    if (target <= fit.floor) return std::numeric_limits<double>::infinity();
    if (!(fit.variance > 0.0)) return std::numeric_limits<double>::quiet_NaN();  // error not falling with spp
    return fit.variance / (target - fit.floor);
}

std::vector<bool> pareto_front(const std::vector<TimedError>& points) {
    std::vector<bool> front(points.size(), true);
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = 0; j < points.size() && front[i]; ++j) {
            const TimedError &a = points[i], &b = points[j];
            const bool dominates = b.seconds <= a.seconds && b.mse <= a.mse && (b.seconds < a.seconds || b.mse < a.mse);
            if (dominates) front[i] = false;
        }
    return front;
}

}  // namespace wt
