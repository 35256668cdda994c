// Filter importance sampling (core/camera/pixel_filter.h): the unit box is the identity, the
// tabulated filters' samples follow their density, Mitchell's signed weights reproduce the
// filter with its negative lobes, and light tracing's pixel choice gives each pixel the filter
// value its own samples give.

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
                                        PixelFilterSettings{FilterKind::blackman_harris, 1.5f},
                                        PixelFilterSettings{FilterKind::mitchell, 4.0f},
                                        PixelFilterSettings{FilterKind::mitchell, 2.5f}}) {
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
                EXPECT_NEAR(received[p], filter.value(x - (float(p) + 0.5f)), 2e-3 * filter.density(0.0f))
                    << name_of(s.kind) << " x " << x << " pixel " << p;
        }
    }
}

// Mitchell & Netravali's cubic (1988, eq. 8), written out here apart from the renderer's.
double mitchell_cubic(double x) {
    constexpr double B = 1.0 / 3.0, C = 1.0 / 3.0;
    x = std::fabs(x);
    if (x < 1.0) return ((12 - 9 * B - 6 * C) * x * x * x + (-18 + 12 * B + 6 * C) * x * x + (6 - 2 * B)) / 6.0;
    if (x < 2.0) return ((-B - 6 * C) * x * x * x + (6 * B + 30 * C) * x * x + (-12 * B - 48 * C) * x + (8 * B + 24 * C)) / 6.0;
    return 0.0;
}

// B = C = 1/3 by hand: k(0) = (6 - 2B) / 6 = 8/9; k(1) = (12 - 9B - 6C - 18 + 12B + 6C + 6 - 2B) / 6
// = B / 6 = 1/18; k(1.5) = (-(B + 6C) 3.375 + (6B + 30C) 2.25 - (12B + 48C) 1.5 + 8B + 24C) / 6
// = -5/144, in the negative lobe; k = 0 from |x| = 2. The filter of width w is k(4d / w), scaled to
// integrate to 1 (k does already, so by 4 / w), and the table holds it at its bins' centres.
TEST(PixelFilter, MitchellIsTheCubicWithItsNegativeLobesAndIntegratesToOne) {
    EXPECT_NEAR(mitchell_cubic(0.0), 8.0 / 9.0, 1e-15);
    EXPECT_NEAR(mitchell_cubic(1.0), 1.0 / 18.0, 1e-15);
    EXPECT_NEAR(mitchell_cubic(1.5), -5.0 / 144.0, 1e-15);
    EXPECT_EQ(mitchell_cubic(2.0), 0.0);
    for (const float width : {4.0f, 2.5f}) {
        const PixelFilter filter{PixelFilterSettings{FilterKind::mitchell, width}};
        EXPECT_TRUE(filter.has_negative_lobes());
        EXPECT_EQ(filter.radius(), 0.5f * width);
        const float bin = width / PixelFilter::kBins;
        for (int i = 0; i < PixelFilter::kBins; ++i) {
            const float centre = -0.5f * width + (float(i) + 0.5f) * bin;
            ASSERT_NEAR(filter.value(centre), mitchell_cubic(4.0 * centre / width) * 4.0 / width, 1e-5) << width << " bin " << i;
        }
        EXPECT_LT(filter.value(0.375f * width), 0.0f);
        EXPECT_EQ(filter.value(0.5f * width), 0.0f);
    }
    const PixelFilter filter{PixelFilterSettings{FilterKind::mitchell, 4.0f}};
    EXPECT_EQ(filter.margin(), 1.5f);
    const float bin = 4.0f / PixelFilter::kBins;
    // Both integrals over the support: the filter's to 1, the sampling density's to 1.
    double integral = 0.0, density_integral = 0.0;
    const int steps = 100000;
    for (int k = 0; k < steps; ++k) {
        const float d = -2.0f + (float(k) + 0.5f) * (4.0f / steps);
        integral += double(filter.value(d)) * (4.0 / steps);
        density_integral += double(filter.density(d)) * (4.0 / steps);
        ASSERT_NEAR(std::fabs(filter.value(d)), filter.density(d) * filter.value(0.5f * bin) / filter.density(0.5f * bin), 1e-6);
    }
    EXPECT_NEAR(integral, 1.0, 1e-4);
    EXPECT_NEAR(density_integral, 1.0, 1e-4);
    // The non-negative filters carry weight 1 exactly: their renders keep their bits.
    for (const FilterKind kind : {FilterKind::box, FilterKind::gaussian, FilterKind::blackman_harris}) {
        const PixelFilter f{PixelFilterSettings{kind, 2.0f}};
        EXPECT_FALSE(f.has_negative_lobes()) << name_of(kind);
        for (int i = 0; i < 1000; ++i) EXPECT_EQ(f.sample({(float(i) + 0.5f) / 1000, 0.37f}).weight, 1.0f) << name_of(kind);
    }
}

// The samples are drawn by |f| (a chi-square of their histogram against the density), every
// sample's weight has the sign of the filter where it lands, and the signed histogram (each
// sample counted with its weight) is the filter, negative lobes and all, within 5 standard
// errors per bin (the standard error from the weights' own spread), and the weights average 1:
// a constant image keeps its value.
TEST(PixelFilter, MitchellSignedSamplesReproduceTheFilter) {
    for (const float width : {4.0f, 2.0f}) {
        const PixelFilter filter{PixelFilterSettings{FilterKind::mitchell, width}};
        expect_samples_follow_the_density(FilterKind::mitchell, width);
        const float r = filter.radius();
        const int bins = 32, n = 400000;
        std::vector<double> signed_sum(bins, 0.0), squares(bins, 0.0), expected(bins, 0.0);
        double weight_sum = 0.0;
        int wrong_signs = 0;
        for (int i = 0; i < n; ++i) {
            const float ux = float((uint64_t(i) * 0x9e3779b9u) & 0xffffffu) * 0x1p-24f;
            const float uy = float((uint64_t(i) * 0x7f4a7c15u + 12345u) & 0xffffffu) * 0x1p-24f;
            const PixelFilter::Sample s = filter.sample({ux, uy});
            const float dx = s.offset.x - 0.5f, dy = s.offset.y - 0.5f;
            // (A sample at a bin's very edge may round into its neighbour's bin, which at a zero
            // crossing has the other sign: a handful, not a pattern.)
            wrong_signs += (s.weight < 0.0f) != ((filter.value(dx) < 0.0f) != (filter.value(dy) < 0.0f));
            weight_sum += s.weight;
            // The x marginal: the y axis's weight averages to 1 by itself, so the x axis alone is
            // the signed histogram of one axis with the 2D weight.
            const int b = std::min(bins - 1, int((dx + r) / (2.0f * r) * bins));
            signed_sum[b] += s.weight;
            squares[b] += double(s.weight) * s.weight;
        }
        const int steps = 64000;
        for (int k = 0; k < steps; ++k) {
            const float d = -r + (float(k) + 0.5f) * (2.0f * r / steps);
            expected[std::min(bins - 1, int(double(k) * bins / steps))] += double(filter.value(d)) * (2.0 * r / steps);
        }
        int negative_bins = 0;
        for (int b = 0; b < bins; ++b) {
            const double mean = signed_sum[b] / n;
            const double standard_error = std::sqrt((squares[b] / n - mean * mean) / n);
            negative_bins += expected[b] < 0.0;
            EXPECT_NEAR(mean, expected[b], 5.0 * standard_error + 1e-9) << "width " << width << " bin " << b;
        }
        EXPECT_GE(negative_bins, 4) << "the lobes are in the histogram";
        EXPECT_LE(wrong_signs, n / 10000) << "weights whose sign is not the filter's where the sample lands";
        EXPECT_NEAR(weight_sum / n, 1.0, 0.01) << width;
    }
}

}  // namespace
}  // namespace wt
