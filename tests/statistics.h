#pragma once
// Small statistics toolkit for the estimator tests: chi-square goodness of fit and normal
// quantiles, so tolerances come from a chosen false-alarm probability, not from guesses.

#include <cmath>
#include <cstddef>
#include <vector>

namespace wt::test {

// Upper-tail probability of the chi-square distribution, P(X >= x) with k degrees of freedom,
// from the regularised incomplete gamma function Q(k/2, x/2) (series below a+1, continued
// fraction above; Numerical Recipes ch. 6.2).
inline double chi_square_survival(double x, double k) {
    const double a = 0.5 * k, z = 0.5 * x;
    if (z <= 0.0) return 1.0;
    const double log_prefix = a * std::log(z) - z - std::lgamma(a);
    if (z < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 10000 && std::fabs(term) > 1e-15 * std::fabs(sum); ++n) {
            term *= z / (a + n);
            sum += term;
        }
        return 1.0 - sum * std::exp(log_prefix);
    }
    double b = z + 1.0 - a, c = 1e300, d = 1.0 / b, h = d;  // modified Lentz
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < 1e-300) d = 1e-300;
        c = b + an / c;
        if (std::fabs(c) < 1e-300) c = 1e-300;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(log_prefix) * h;
}

struct ChiSquareResult {
    double statistic = 0.0;
    int degrees_of_freedom = 0;
    double p_value = 1.0;
};

// Pearson's test of observed counts against expected counts. Cells with expected < 5 are pooled,
// as the chi-square approximation requires; an observation in a cell whose expected count is
// zero is an outright failure (p = 0).
inline ChiSquareResult chi_square_test(const std::vector<double>& observed, const std::vector<double>& expected) {
    ChiSquareResult r;
    double pooled_observed = 0.0, pooled_expected = 0.0;
    int cells = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] == 0.0) {
            if (observed[i] > 0.0) return {INFINITY, 0, 0.0};
            continue;
        }
        if (expected[i] < 5.0) {
            pooled_observed += observed[i];
            pooled_expected += expected[i];
            continue;
        }
        const double diff = observed[i] - expected[i];
        r.statistic += diff * diff / expected[i];
        ++cells;
    }
    if (pooled_expected > 0.0) {
        const double diff = pooled_observed - pooled_expected;
        r.statistic += diff * diff / pooled_expected;
        ++cells;
    }
    r.degrees_of_freedom = cells - 1;
    r.p_value = chi_square_survival(r.statistic, r.degrees_of_freedom);
    return r;
}

// Two-sided standard normal quantile: the z with P(|Z| > z) = alpha (bisection on erfc).
inline double normal_two_sided_quantile(double alpha) {
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// Smallest k with P(Binomial(n, p) >= k) <= alpha: how many independent per-pixel test failures
// chance alone allows.
inline int binomial_upper_bound(int n, double p, double alpha) {
    double tail = 1.0;  // P(X >= k)
    double pk = std::pow(1.0 - p, n);  // P(X = k), starting at k = 0
    for (int k = 0; k <= n; ++k) {
        if (tail <= alpha) return k;
        tail -= pk;
        pk *= double(n - k) / double(k + 1) * p / (1.0 - p);
    }
    return n + 1;
}

}  // namespace wt::test
