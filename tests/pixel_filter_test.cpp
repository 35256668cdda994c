// Filter importance sampling (core/camera/pixel_filter.h): the unit box is the identity, the
// tabulated filters' samples follow their density, and light tracing's pixel choice gives each
// pixel the density of its own samples.

#include <cmath>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "core/camera/pixel_filter.h"
#include "statistics.h"

namespace wt {
namespace {

TEST(PixelFilter, UnitBoxIsTheUniformPointItselfBitForBit) {
    const PixelFilter box{PixelFilterSettings{}};
    EXPECT_TRUE(box.is_unit_box());
    EXPECT_EQ(box.margin(), 0.0f);
    for (int i = 0; i < 4096; ++i) {
        const glm::vec2 u(float(i) * 0x1p-12f, float((i * 2897) % 4096) * 0x1p-12f + 0x1p-24f);
        const glm::vec2 o = box.offset(u);
        EXPECT_EQ(std::memcmp(&o, &u, sizeof o), 0) << u.x << " " << u.y;
    }
    // A wider box spreads the same points over its width, about the pixel's centre.
    const PixelFilter wide{PixelFilterSettings{FilterKind::box, 2.0f}};
    EXPECT_FALSE(wide.is_unit_box());
    EXPECT_EQ(wide.offset({0.0f, 0.75f}), glm::vec2(-0.5f, 1.0f));
    EXPECT_EQ(wide.margin(), 0.5f);
}

// The offsets' histogram against the filter's density, by chi-square, and the density's integral.
void expect_samples_follow_the_density(FilterKind kind, float width) {
    const PixelFilter filter{PixelFilterSettings{kind, width}};
    const float r = filter.radius();
    const int bins = 40, n = 200000;
    std::vector<double> observed(bins, 0.0), expected(bins, 0.0);
    for (int i = 0; i < n; ++i) {
        // A low-discrepancy u is fine for the histogram: what is tested is the inverse map.
        const float u = float((uint64_t(i) * 0x9e3779b9u) & 0xffffffu) * 0x1p-24f;
        const float d = filter.offset({u, u}).x - 0.5f;
        ASSERT_GE(d, -r);
        ASSERT_LT(d, r);
        observed[std::min(bins - 1, int((d + r) / (2.0f * r) * bins))] += 1.0;
    }
    double integral = 0.0;
    const int steps = 100000;
    for (int k = 0; k < steps; ++k) {
        const float d = -r + (float(k) + 0.5f) * (2.0f * r / steps);
        const double p = filter.density(d) * (2.0 * r / steps);
        integral += p;
        expected[std::min(bins - 1, int(double(k) * bins / steps))] += p * n;
    }
    EXPECT_NEAR(integral, 1.0, 1e-4);
    const test::ChiSquareResult chi = test::chi_square_test(observed, expected);
    EXPECT_GT(chi.p_value, 1e-4) << name_of(kind) << " chi2 " << chi.statistic << " dof " << chi.degrees_of_freedom;
    // And it is the filter's shape: the centre denser than near the edge, symmetric.
    EXPECT_GT(filter.density(0.0f), 5.0f * filter.density(0.95f * r));
    EXPECT_NEAR(filter.density(-0.37f * r), filter.density(0.37f * r), 1e-3 * filter.density(0.0f));  // inside mirror bins
    EXPECT_EQ(filter.density(r), 0.0f);
}

TEST(PixelFilter, GaussianAndBlackmanHarrisSamplesFollowTheirDensity) {
    expect_samples_follow_the_density(FilterKind::gaussian, 1.5f);
    expect_samples_follow_the_density(FilterKind::gaussian, 3.0f);
    expect_samples_follow_the_density(FilterKind::blackman_harris, 1.5f);
    expect_samples_follow_the_density(FilterKind::blackman_harris, 4.0f);
}

// Averaged over u, the pixel choice gives pixel P weight x [P chosen] = density(x - centre_P):
// what P's own camera samples give the film point x.
TEST(PixelFilter, SplatPixelChoiceGivesEachPixelItsFilterWeight) {
    for (const PixelFilterSettings s : {PixelFilterSettings{FilterKind::gaussian, 3.0f}, PixelFilterSettings{FilterKind::box, 2.0f},
                                        PixelFilterSettings{FilterKind::blackman_harris, 1.5f}}) {
        const PixelFilter filter(s);
        for (const float x : {10.0f, 10.3f, 10.5f, 10.99f}) {
            std::vector<double> received(40, 0.0);
            const int n = 100000;
            for (int i = 0; i < n; ++i) {
                const PixelFilter::AxisChoice c = filter.choose_pixel(x, (float(i) + 0.5f) / n);
                ASSERT_GE(c.pixel, 0);
                ASSERT_LT(c.pixel, 40);
                received[c.pixel] += c.weight / n;
            }
            for (int p = 0; p < 40; ++p)
                EXPECT_NEAR(received[p], filter.density(x - (float(p) + 0.5f)), 2e-3 * filter.density(0.0f))
                    << name_of(s.kind) << " x " << x << " pixel " << p;
        }
    }
}

}  // namespace
}  // namespace wt
