#pragma once
// A render of the oracle's room against the oracle's prediction, region by region (see
// oracle/region_prediction.h for what a region is). Per region and channel, the rendered mean
// over the region's pixels must be within z standard errors of the prediction, plus the
// oracle's own error bound; z comes from a family-wise false-alarm rate split over every
// region, channel and the pooled image (Bonferroni). The standard error comes from the film's
// per-pixel sums of squares: the pixels are independent, so the variance of the region's mean
// is the sum of the pixels' variances of the mean over the region's pixel count squared.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/film/film.h"
#include "oracle/region_prediction.h"
#include "statistics.h"

namespace wt::test {

struct RegionVerdict {
    std::string name;
    int pixels = 0;
    double rendered[3]{}, predicted[3]{}, standard_error[3]{}, oracle_bound[3]{};
    // (rendered - predicted) / standard error, and whether |difference| > z * se + bound.
    double z[3]{};
    bool fails[3]{};
};

struct OracleComparison {
    std::vector<RegionVerdict> regions;  // the view's regions, then every wall pooled
    double z_limit = 0.0;
    int failures = 0;
    double largest_z = 0.0;            // over the regions and channels, |z|
    double largest_oracle_share = 0.0; // oracle bound / (z_limit * standard error), the worst
};

inline const char* wall_name(int wall) {
    static const char* const names[] = {"wall x=0", "wall x=max", "wall y=0", "wall y=max", "floor", "ceiling"};
    return names[wall];
}

inline std::string region_name(const oracle::PixelRegion& r) {
    if (r.cell_a < 0) return wall_name(r.wall);
    return std::string(wall_name(r.wall)) + " cell (" + std::to_string(r.cell_a) + ", " + std::to_string(r.cell_b) + ")";
}

inline RegionVerdict judge(const std::string& name, const Film& film, const oracle::ViewPrediction& view,
                           const std::vector<int>& pixels, double z_limit) {
    RegionVerdict v;
    v.name = name;
    v.pixels = int(pixels.size());
    double mean[3] = {0, 0, 0}, variance[3] = {0, 0, 0}, predicted[3] = {0, 0, 0}, bound[3] = {0, 0, 0};
    for (int p : pixels) {
        const glm::dvec3 m = film.pixel_mean(uint32_t(p));
        const glm::dvec3 s2 = film.pixel_sample_variance(uint32_t(p)) / double(film.pixel_count(uint32_t(p)));
        const oracle::PixelPrediction& o = view.pixels[std::size_t(p)];
        for (int c = 0; c < 3; ++c) {
            mean[c] += m[c];
            variance[c] += s2[c];
            predicted[c] += o.radiance[c];
            bound[c] += o.error_bound[c];  // the bound of a mean is at most the mean of the bounds
        }
    }
    const double n = double(pixels.size());
    for (int c = 0; c < 3; ++c) {
        v.rendered[c] = mean[c] / n;
        v.predicted[c] = predicted[c] / n;
        v.standard_error[c] = std::sqrt(variance[c]) / n;
        v.oracle_bound[c] = bound[c] / n;
        const double difference = v.rendered[c] - v.predicted[c];
        v.z[c] = v.standard_error[c] > 0.0 ? difference / v.standard_error[c] : 0.0;
        v.fails[c] = std::fabs(difference) > z_limit * v.standard_error[c] + v.oracle_bound[c];
    }
    return v;
}

// Every region of the view (each wall, each cell) and all of them pooled. `family_alpha`: the
// chance that a correct renderer fails somewhere in this comparison, for a random seed.
inline OracleComparison compare_with_oracle(const Film& film, const oracle::ViewPrediction& view, double family_alpha = 1e-3) {
    OracleComparison out;
    out.z_limit = normal_two_sided_quantile(family_alpha / double(3 * (view.regions.size() + 1)));
    std::vector<int> all;
    for (const oracle::PixelRegion& r : view.regions) {
        out.regions.push_back(judge(region_name(r), film, view, r.pixels, out.z_limit));
        if (r.cell_a < 0) all.insert(all.end(), r.pixels.begin(), r.pixels.end());
    }
    out.regions.push_back(judge("every wall pooled", film, view, all, out.z_limit));
    for (const RegionVerdict& v : out.regions) {
        for (int c = 0; c < 3; ++c) {
            out.failures += v.fails[c];
            out.largest_z = std::fmax(out.largest_z, std::fabs(v.z[c]));
            if (v.standard_error[c] > 0.0)
                out.largest_oracle_share = std::fmax(out.largest_oracle_share, v.oracle_bound[c] / (out.z_limit * v.standard_error[c]));
        }
    }
    return out;
}

inline void print_comparison(const OracleComparison& c, const char* label) {
    std::printf("%s: |z| limit %.2f, %d failing, largest |z| %.2f, oracle bound at most %.0f %% of the statistical tolerance\n",
                label, c.z_limit, c.failures, c.largest_z, 100.0 * c.largest_oracle_share);
    for (const RegionVerdict& v : c.regions) {
        std::printf("  %-26s %4d px", v.name.c_str(), v.pixels);
        for (int ch = 0; ch < 3; ++ch)
            std::printf(" | %.5f vs %.5f se %.5f bound %.5f z %6.2f%s", v.rendered[ch], v.predicted[ch], v.standard_error[ch],
                        v.oracle_bound[ch], v.z[ch], v.fails[ch] ? " FAIL" : "");
        std::printf("\n");
    }
}

}  // namespace wt::test
