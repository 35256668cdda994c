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
    // In float the running sum would stall near 2^24 * ulp; double keeps 1e-9 relative error.
    EXPECT_NEAR(film.pixel_mean(0).x, double(0.1f), 1e-9);
}

}  // namespace
}  // namespace wt
