// Reading images for comparison: linear EXR bits kept, sRGB PNGs decoded, grey expanded, and
// files that cannot be compared refused with their name.

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "core/film/image_output.h"
#include "core/image_io/rgb_image_input.h"

namespace wt {
namespace {

namespace fs = std::filesystem;

class ImageInput : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("wavetrace-image-input-test-" + std::to_string(getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    void write_raw(const std::string& name, int channels, const std::vector<float>& values, int width) const {
        auto out = OIIO::ImageOutput::create(path(name));
        ASSERT_TRUE(out);
        const OIIO::ImageSpec spec(width, int(values.size()) / (width * channels), channels, OIIO::TypeDesc::FLOAT);
        ASSERT_TRUE(out->open(path(name), spec) && out->write_image(OIIO::TypeDesc::FLOAT, values.data()) && out->close());
    }
    fs::path dir_;
};

const std::vector<float> kPixels = {0.0f, 0.5f, 1.0f, 2.0f, 0.001f, 0.18f};  // 2x1 RGB

TEST_F(ImageInput, ExrReadsBackBitForBit) {
    write_image(path("a.exr"), 2, 1, kPixels);
    const RgbImage image = read_rgb_image(path("a.exr"));
    EXPECT_EQ(image.width, 2);
    EXPECT_EQ(image.height, 1);
    EXPECT_EQ(image.rgb, kPixels);
}

TEST_F(ImageInput, SrgbPngIsDecodedToLinear) {
    write_image(path("a.png"), 2, 1, kPixels);
    const RgbImage image = read_rgb_image(path("a.png"));
    // Within half an 8-bit step of the curve, which is what the PNG kept (2.0 was clamped to 1).
    const std::vector<float> expected = {0.0f, 0.5f, 1.0f, 1.0f, 0.001f, 0.18f};
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(image.rgb[i], expected[i], 0.004f) << i;
    EXPECT_NEAR(srgb_to_linear(linear_to_srgb(0.5f)), 0.5f, 1e-6f);
    EXPECT_NEAR(srgb_to_linear(linear_to_srgb(0.002f)), 0.002f, 1e-7f);
}

TEST_F(ImageInput, GreyBecomesRgb) {
    write_raw("grey.exr", 1, {0.25f, 4.0f}, 2);
    EXPECT_EQ(read_rgb_image(path("grey.exr")).rgb, (std::vector<float>{0.25f, 0.25f, 0.25f, 4.0f, 4.0f, 4.0f}));
}

TEST_F(ImageInput, RefusesWhatCannotBeCompared) {
    const auto message_of = [](const std::string& p) {
        try {
            read_rgb_image(p);
        } catch (const ImageError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message_of(path("missing.exr")), path("missing.exr") + ": no such file");
    std::ofstream(path("text.exr")) << "not an image";
    EXPECT_NE(message_of(path("text.exr")).find(path("text.exr") + ": cannot read it as an image"), std::string::npos);
    write_raw("two.exr", 2, {0.0f, 1.0f}, 1);
    EXPECT_NE(message_of(path("two.exr")).find("2 channels"), std::string::npos);
    write_raw("nan.exr", 3, {0.0f, 0.0f, 0.0f, 1.0f, std::nanf(""), 1.0f}, 2);
    EXPECT_NE(message_of(path("nan.exr")).find("pixel (1,0) channel 1"), std::string::npos) << message_of(path("nan.exr"));
}

}  // namespace
}  // namespace wt
