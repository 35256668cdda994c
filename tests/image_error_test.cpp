// The error metrics against values worked out by hand on tiny images, and against OpenImageIO's
// own compare on a masked region.

#include <cmath>
#include <limits>
#include <random>

#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include "core/image_metrics/image_metrics.h"

namespace wt {
namespace {

RgbImage uniform(int width, int height, float value) {
    return {width, height, std::vector<float>(3 * std::size_t(width) * std::size_t(height), value)};
}

float& at(RgbImage& i, int x, int y, int c) { return i.rgb[3 * (std::size_t(y) * std::size_t(i.width) + std::size_t(x)) + std::size_t(c)]; }

// A 2x2 reference of 0.5 everywhere; the image is off by +0.25 in G at (1,0) and by -0.125 in B
// at (0,1). Binary fractions, so every expected value below is exact arithmetic.
struct TwoDifferences : ::testing::Test {
    RgbImage reference = uniform(2, 2, 0.5f);
    RgbImage image = reference;
    void SetUp() override {
        at(image, 1, 0, 1) = 0.75f;
        at(image, 0, 1, 2) = 0.375f;
    }
};

TEST_F(TwoDifferences, PerChannelAndOverall) {
    const ImageErrorReport r = image_error(image, reference);
    EXPECT_EQ(r.pixels, 4u);
    const ErrorMetrics &red = r.channel[0], &green = r.channel[1], &blue = r.channel[2];
    EXPECT_EQ(red.rmse, 0.0);
    EXPECT_EQ(red.psnr, std::numeric_limits<double>::infinity());
    EXPECT_EQ(red.mean_ratio, 1.0);
    EXPECT_NEAR(green.rmse, 0.125, 1e-12);  // sqrt(0.25^2 / 4)
    EXPECT_NEAR(blue.rmse, 0.0625, 1e-12);  // sqrt(0.125^2 / 4)
    EXPECT_NEAR(green.psnr, 20.0 * std::log10(8.0), 1e-9);
    EXPECT_NEAR(green.rel_mse, 0.0625 / 0.26 / 4.0, 1e-12);  // 0.25^2 / (0.5^2 + 0.01), one pixel of four
    EXPECT_NEAR(blue.rel_mse, 0.015625 / 0.26 / 4.0, 1e-12);
    EXPECT_NEAR(green.mean_ratio, 2.25 / 2.0, 1e-12);
    EXPECT_NEAR(blue.mean_ratio, 1.875 / 2.0, 1e-12);
    EXPECT_NEAR(r.overall.rmse, std::sqrt((0.0625 + 0.015625) / 12.0), 1e-12);
    EXPECT_NEAR(r.overall.rel_mse, (0.0625 + 0.015625) / 0.26 / 12.0, 1e-12);
    EXPECT_NEAR(r.overall.mean_ratio, 6.125 / 6.0, 1e-12);
    EXPECT_EQ(r.overall.max_error, 0.25);
    EXPECT_EQ(r.overall.max_x, 1);
    EXPECT_EQ(r.overall.max_y, 0);
    EXPECT_EQ(r.overall.max_channel, 1);
    EXPECT_EQ(blue.max_error, 0.125);
    EXPECT_EQ(blue.max_x, 0);
    EXPECT_EQ(blue.max_y, 1);
    EXPECT_EQ(blue.max_channel, 2);
}

TEST_F(TwoDifferences, MaskCountsOnlyKeptPixels) {
    RgbImage mask = uniform(2, 2, 0.0f);
    at(mask, 1, 0, 0) = 1.0f;  // keeps the pixel with the G difference only
    const std::vector<uint8_t> kept = pixels_kept_by(mask);
    const ImageErrorReport r = image_error(image, reference, &kept);
    EXPECT_EQ(r.pixels, 1u);
    EXPECT_NEAR(r.channel[1].rmse, 0.25, 1e-12);
    EXPECT_EQ(r.channel[2].rmse, 0.0);  // the B difference is in a dropped pixel
    EXPECT_NEAR(r.overall.rmse, std::sqrt(0.0625 / 3.0), 1e-12);
    EXPECT_NEAR(r.overall.rel_mse, 0.0625 / 0.26 / 3.0, 1e-12);
    EXPECT_NEAR(r.channel[1].mean_ratio, 1.5, 1e-12);

    at(mask, 1, 0, 0) = 0.0f;
    at(mask, 0, 1, 0) = 0.5f;  // any non-zero value keeps a pixel
    const std::vector<uint8_t> other = pixels_kept_by(mask);
    const ImageErrorReport s = image_error(image, reference, &other);
    EXPECT_EQ(s.channel[1].rmse, 0.0);
    EXPECT_NEAR(s.channel[2].rmse, 0.125, 1e-12);
}

TEST(ImageError, IdenticalImagesHaveNoError) {
    const RgbImage a = uniform(3, 2, 0.25f);
    const ImageErrorReport r = image_error(a, a);
    EXPECT_EQ(r.overall.rmse, 0.0);
    EXPECT_EQ(r.overall.rel_mse, 0.0);
    EXPECT_EQ(r.overall.mean_ratio, 1.0);
    EXPECT_EQ(r.overall.psnr, std::numeric_limits<double>::infinity());
}

TEST(ImageError, BlackReferenceHasNoMeanRatio) {
    const ImageErrorReport r = image_error(uniform(1, 1, 0.1f), uniform(1, 1, 0.0f));
    EXPECT_TRUE(std::isnan(r.overall.mean_ratio));
    EXPECT_NEAR(r.overall.rel_mse, 0.01 / 0.01, 1e-6);  // the 0.01 is what keeps black pixels finite
}

TEST(ImageError, RefusesMismatchedSizesAndEmptyMasks) {
    try {
        image_error(uniform(2, 2, 0.0f), uniform(2, 3, 0.0f));
        FAIL() << "no error for different sizes";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("2x2"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("2x3"), std::string::npos) << e.what();
    }
    const std::vector<uint8_t> none(4, 0), short_mask(3, 1);
    EXPECT_THROW(image_error(uniform(2, 2, 0.0f), uniform(2, 2, 0.0f), &none), std::invalid_argument);
    EXPECT_THROW(image_error(uniform(2, 2, 0.0f), uniform(2, 2, 0.0f), &short_mask), std::invalid_argument);
}

// A mask keeping a rectangle must give what OpenImageIO's compare gives over that rectangle, and
// no mask what it gives over the whole image (our sums are our own: core does not link it).
TEST(ImageError, MaskedRectangleAgreesWithOpenImageIOCompareOverItsROI) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> value(0.0f, 2.0f);
    RgbImage a = uniform(7, 5, 0.0f), b = a, mask = a;
    for (float& v : a.rgb) v = value(rng);
    for (float& v : b.rgb) v = value(rng);
    const OIIO::ROI rect(2, 6, 1, 4, 0, 1, 0, 3);  // x in [2, 6), y in [1, 4)
    for (int y = rect.ybegin; y < rect.yend; ++y)
        for (int x = rect.xbegin; x < rect.xend; ++x) at(mask, x, y, 0) = 1.0f;
    const std::vector<uint8_t> kept = pixels_kept_by(mask);
    const ImageErrorReport r = image_error(a, b, &kept);

    const OIIO::ImageSpec spec(7, 5, 3, OIIO::TypeDesc::FLOAT);
    const OIIO::ImageBuf A(spec, a.rgb.data()), B(spec, b.rgb.data());
    const float never = std::numeric_limits<float>::max();
    const auto oiio = OIIO::ImageBufAlgo::compare(A, B, never, never, 0.0f, 0.0f, rect, 1);
    ASSERT_FALSE(oiio.error);
    EXPECT_EQ(r.pixels, 12u);
    // OpenImageIO takes the differences in float, we in double: equal to float rounding.
    EXPECT_NEAR(r.overall.rmse, oiio.rms_error, 1e-6 * oiio.rms_error);
    EXPECT_NEAR(r.overall.psnr, 20.0 * std::log10(1.0 / oiio.rms_error), 1e-5);  // ours has peak 1, OpenImageIO's the brightest value
    EXPECT_EQ(r.overall.max_error, oiio.maxerror);
    EXPECT_EQ(r.overall.max_x, oiio.maxx);
    EXPECT_EQ(r.overall.max_y, oiio.maxy);
    EXPECT_EQ(r.overall.max_channel, oiio.maxc);

    // And the whole image: every metric of ours that OpenImageIO also computes.
    const ImageErrorReport whole = image_error(a, b);
    const auto all = OIIO::ImageBufAlgo::compare(A, B, never, never, 0.0f, 0.0f, OIIO::ROI(), 1);
    EXPECT_NEAR(whole.overall.rmse, all.rms_error, 1e-6 * all.rms_error);
    double squares = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) squares += double(a.rgb[i] - b.rgb[i]) * double(a.rgb[i] - b.rgb[i]);
    EXPECT_NEAR(whole.overall.rmse, std::sqrt(squares / double(a.rgb.size())), 1e-6);
}

}  // namespace
}  // namespace wt
