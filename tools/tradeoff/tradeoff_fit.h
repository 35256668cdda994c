#pragma once
// What the trade tool concludes from its measurements: fits of error against samples per pixel,
// the samples and time to reach an error, and the Pareto front of error against time.
//
// The error is fitted against spp, not time: with a fixed seed the error at each spp is exact,
// while times on a shared machine are noisy, so a fit against time would put the timing noise
// into the floor. Time enters afterwards, as the configuration's seconds per spp.

#include <cstddef>
#include <vector>

namespace wt {

struct SampledError {
    double spp = 0.0;
    double mse = 0.0;  // mean squared error against the reference (RMSE^2)
};

struct ErrorFit {
    // log RMSE = log(c) + slope * log(spp), least squares: slope -1/2 is a Monte Carlo estimator
    // converging at its usual rate; shallower means a floor (bias) or heavy tails.
    double slope = 0.0, c = 0.0;
    // MSE(spp) = floor + variance / spp: bias^2 (plus the reference's own noise) and the variance
    // of one sample per pixel. Fitted with relative residuals, since the points span decades of
    // error; floor >= 0.
    double floor = 0.0, variance = 0.0;
    std::size_t points = 0;
};

// Needs at least two points with distinct spp; throws std::invalid_argument otherwise.
ErrorFit fit_error_against_spp(const std::vector<SampledError>& points);

// The spp the fit needs for MSE target_rmse^2; +infinity when the floor is at or above it, NaN
// when the fitted error does not fall with spp.
double spp_to_reach(const ErrorFit& fit, double target_rmse);

struct TimedError {
    double seconds = 0.0;
    double mse = 0.0;
};

// One flag per point: no other point is at least as fast and at least as accurate and better in
// one of the two (the front of the error-against-time plot).
std::vector<bool> pareto_front(const std::vector<TimedError>& points);

}  // namespace wt
