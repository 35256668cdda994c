// The film: means and variances, NaN/Inf never reaching the image, accumulation without drift.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/film/film.h"

namespace wt {
namespace {

TEST(Film, MeanAndUnbiasedVariancePerPixel) {
    Film film(2, 1);
    for (float v : {1.0f, 2.0f, 3.0f, 4.0f}) EXPECT_TRUE(film.add_sample(1, glm::vec3(v, 2 * v, 0)));
    EXPECT_EQ(film.pixel_count(0), 0u);
    EXPECT_EQ(film.pixel_count(1), 4u);
    EXPECT_DOUBLE_EQ(film.pixel_mean(1).x, 2.5);
    EXPECT_DOUBLE_EQ(film.pixel_mean(1).y, 5.0);
    EXPECT_DOUBLE_EQ(film.pixel_sample_variance(1).x, 5.0 / 3.0);
    EXPECT_DOUBLE_EQ(film.pixel_sample_variance(1).y, 20.0 / 3.0);
    const std::vector<float> rgb = film.resolve();
    EXPECT_EQ(rgb[0], 0.0f);  // no samples: black, not NaN
    EXPECT_FLOAT_EQ(rgb[3], 2.5f);
}

TEST(Film, NonFiniteSamplesAreRejectedAndNeverReachTheImage) {
    Film film(1, 1);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_TRUE(film.add_sample(0, glm::vec3(1.0f)));
    EXPECT_FALSE(film.add_sample(0, glm::vec3(nan, 0, 0)));
    EXPECT_FALSE(film.add_sample(0, glm::vec3(0, inf, 0)));
    EXPECT_FALSE(film.add_sample(0, glm::vec3(0, 0, -inf)));
    EXPECT_EQ(film.pixel_count(0), 1u);
    for (float c : film.resolve()) EXPECT_FLOAT_EQ(c, 1.0f);
}

TEST(Film, TenMillionSamplesAccumulateWithoutDrift) {
    Film film(1, 1);
    for (int i = 0; i < 10000000; ++i) film.add_sample(0, glm::vec3(0.1f));
    // In float the running sum would stall near 2^24 * ulp; the fixed-point sum rounds each
    // sample to 2^-40 once, an error of at most 2^-41 per sample in the mean.
    EXPECT_NEAR(film.pixel_mean(0).x, double(0.1f), 0x1p-41);
}

// The property split renders rely on: the same samples give the same bits in any order and
// any split into films added later. A double sum passes neither: both sides are asserted.
TEST(Film, SumsAreExactWhateverTheOrderAndSplit) {
    std::vector<float> values;
    uint64_t state = 12345;
    for (int i = 0; i < 1000; ++i) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        const int exponent = int(state >> 59) - 16;  // magnitudes 2^-16 .. 2^15
        values.push_back(std::ldexp(float((state >> 20) & 0xffffff) / float(1 << 24), exponent));
    }
    Film forward(1, 1), backward(1, 1), first_half(1, 1), second_half(1, 1);
    double double_forward = 0.0, double_backward = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        forward.add_sample(0, glm::vec3(values[i]));
        backward.add_sample(0, glm::vec3(values[values.size() - 1 - i]));
        (i < 400 ? first_half : second_half).add_sample(0, glm::vec3(values[i]));
        double_forward += values[i];
        double_backward += values[values.size() - 1 - i];
    }
    EXPECT_NE(double_forward, double_backward) << "these values were chosen so a double sum depends on the order";
    EXPECT_TRUE(forward == backward);
    second_half.add_film(first_half);
    EXPECT_TRUE(forward == second_half);
    EXPECT_EQ(forward.pixel_count(0), 1000u);
}

TEST(Film, ValuesBeyondTheFixedPointRangeAreRefusedAndLeaveNoTrace) {
    Film film(1, 1, {"depth"});
    const float depth = 2.0f;
    EXPECT_TRUE(film.add_sample(0, glm::vec3(1.0f, 2.0f, 3.0f), &depth));
    const Film before = film;
    // The square of 2^44 is 2^88, beyond 2^86: refused even though the value itself fits.
    EXPECT_FALSE(film.add_sample(0, glm::vec3(1.0f, 0x1p44f, 1.0f), &depth));
    const float huge_depth = 1e30f;
    EXPECT_FALSE(film.add_sample(0, glm::vec3(1.0f), &huge_depth)) << "an extra channel out of range refuses the sample";
    EXPECT_TRUE(film == before);
    EXPECT_TRUE(film.add_sample(0, glm::vec3(0x1p42f), &depth)) << "2^42 and its square are in range";
    EXPECT_EQ(film.pixel_count(0), 2u);
    EXPECT_DOUBLE_EQ(film.extra_mean(0, 0), 2.0);
    EXPECT_DOUBLE_EQ(film.pixel_mean(0).x, (1.0 + 0x1p42) / 2.0);
}

// A sum that would overflow in a later channel refuses the sample after the earlier channels
// were added: they are taken back, so the film is the same bits as before. The same for splats.
TEST(Film, ASumOverflowingInALaterChannelLeavesNoTrace) {
    const FixedPoint largest = ~(FixedPoint(1) << 127);
    Film film(2, 1, {"depth", Film::splat_channels[0], Film::splat_channels[1], Film::splat_channels[2]});
    const float depth = 2.0f;
    EXPECT_TRUE(film.add_sample(0, glm::vec3(1.0f), &depth));
    EXPECT_TRUE(film.add_splat(0, glm::vec3(1.0f)));
    const std::size_t stride = film.channels_per_pixel();
    film.raw_sums()[4] = largest;               // pixel 0's sum of green squared: full
    film.raw_sums()[stride - 1] = largest - 1;  // pixel 0's blue splat: one step from full
    const Film before = film;
    EXPECT_FALSE(film.add_sample(0, glm::vec3(1.0f, 1.0f, 1.0f), &depth)) << "green squared overflows";
    EXPECT_FALSE(film.add_splat(0, glm::vec3(1.0f, 1.0f, 1.0f))) << "the blue splat overflows";
    EXPECT_TRUE(film == before);
    // The other side: a sample and a splat whose sums all fit still go in, and move the sums.
    EXPECT_TRUE(film.add_sample(0, glm::vec3(1.0f, 0.0f, 1.0f), &depth));
    EXPECT_TRUE(film.add_splat(0, glm::vec3(1.0f, 1.0f, 0.0f)));
    EXPECT_EQ(film.pixel_count(0), 2u);
    EXPECT_EQ(film.raw_sums()[0], 2 * FixedPoint(fixed_point_one));
    EXPECT_EQ(film.raw_sums()[stride - 3], 2 * FixedPoint(fixed_point_one));
    EXPECT_FALSE(film == before);
}

TEST(Film, AddingFilmsChecksLayoutAndOverflow) {
    Film a(2, 2), b(2, 2), other_size(2, 1), other_channels(2, 2, {"depth"});
    EXPECT_THROW(a.add_film(other_size), std::invalid_argument);
    EXPECT_THROW(a.add_film(other_channels), std::invalid_argument);
    a.raw_counts()[3] = 0xffffffffu;
    b.raw_counts()[3] = 1;
    const Film unchanged = a;
    EXPECT_THROW(a.add_film(b), std::overflow_error);
    EXPECT_TRUE(a == unchanged);
}

}  // namespace
}  // namespace wt
