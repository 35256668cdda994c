#pragma once
// What the trade tool concludes from (time, error) measurements: fits of error against time,
// the time to reach an error, and the Pareto front.

#include <cstddef>
#include <vector>

namespace wt {

struct TimedError {
    double seconds = 0.0;
    double mse = 0.0;  // mean squared error against the reference (RMSE^2)
};

struct ErrorFit {
    // log RMSE = log(c) + slope * log(t), least squares: slope -1/2 is a Monte Carlo estimator
    // converging at its usual rate; shallower means a floor (bias) or heavy tails.
    double slope = 0.0, c = 0.0;
    // MSE(t) = floor + variance_seconds / t: bias^2 (plus the reference's own noise) and the
    // variance of one second's worth of samples. Fitted with relative residuals, since the points
    // span decades of error; floor >= 0.
    double floor = 0.0, variance_seconds = 0.0;
    std::size_t points = 0;
};

// Needs at least two points with distinct times; throws std::invalid_argument otherwise.
ErrorFit fit_error_against_time(const std::vector<TimedError>& points);

// The time the fit needs for MSE target_rmse^2; +infinity when the floor is at or above it, NaN
// when the fitted error does not fall with time.
double seconds_to_reach(const ErrorFit& fit, double target_rmse);

// One flag per point: no other point is at least as fast and at least as accurate and better in
// one of the two (the front of the error-against-time plot).
std::vector<bool> pareto_front(const std::vector<TimedError>& points);

}  // namespace wt
