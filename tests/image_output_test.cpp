// Image files: the right encoding per extension, read back through OpenImageIO, and no
// half-written or temporary files left behind by a failure.

#include <filesystem>
#include <unistd.h>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "core/film/image_output.h"

namespace wt {
namespace {

namespace fs = std::filesystem;

class ImageOutput : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("wavetrace-image-test-" + std::to_string(getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    std::size_t files_in_dir() const { return std::size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator())); }
    fs::path dir_;
};

const std::vector<float> kPixels = {0.0f, 0.5f, 1.0f, 2.0f, 0.001f, 0.18f};  // 2x1 RGB

TEST_F(ImageOutput, ExrKeepsLinearFloatRadiance) {
    write_image(path("a.exr"), 2, 1, kPixels);
    auto in = OIIO::ImageInput::open(path("a.exr"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().width, 2);
    EXPECT_EQ(in->spec().nchannels, 3);
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::FLOAT);
    std::vector<float> back(6);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, back.data()));
    EXPECT_EQ(back, kPixels);  // 2.0 above white survives
    EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(ImageOutput, PngIsSrgbEncodedAndClamped) {
    write_image(path("a.png"), 2, 1, kPixels);
    auto in = OIIO::ImageInput::open(path("a.png"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
    std::vector<uint8_t> back(6);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, back.data()));
    EXPECT_EQ(back[0], 0);
    EXPECT_EQ(back[1], 188);  // sRGB(0.5) = 0.7354
    EXPECT_EQ(back[2], 255);
    EXPECT_EQ(back[3], 255);  // 2.0 clamped
    EXPECT_EQ(back[4], 3);    // linear segment: 12.92 * 0.001 * 255
    EXPECT_EQ(back[5], 118);  // middle grey 0.18 -> 0.4613
}

TEST_F(ImageOutput, SrgbCurveIsContinuousAtItsKnee) {
    EXPECT_NEAR(linear_to_srgb(0.0031308f), linear_to_srgb(0.0031309f), 1e-5f);
    EXPECT_EQ(linear_to_srgb(-1.0f), 0.0f);
    EXPECT_EQ(linear_to_srgb(5.0f), 1.0f);
}

TEST_F(ImageOutput, UnknownExtensionIsRefusedNamingThePath) {
    try {
        check_output_path(path("a.xyz"));
        FAIL() << "accepted .xyz";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("a.xyz"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("unsupported"), std::string::npos);
    }
}

TEST_F(ImageOutput, MissingDirectoryIsRefusedBeforeRendering) {
    EXPECT_THROW(check_output_path(path("no/such/dir/a.png")), ImageError);
    EXPECT_NO_THROW(check_output_path(path("a.png")));
}

TEST_F(ImageOutput, AnOutputThatIsADirectoryIsRefusedBeforeRendering) {
    fs::create_directories(path("existing_directory.png"));
    try {
        check_output_path(path("existing_directory.png"));
        ADD_FAILURE() << "no error";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("existing_directory.png: is a directory"), std::string::npos) << e.what();
    }
    EXPECT_NO_THROW(check_output_path(path("good.png")));
}

TEST_F(ImageOutput, ANameTooLongForTheTemporaryFileIsRefusedBeforeRendering) {
    // 254 bytes fits the usual 255-byte limit; ".NAME.tmp-PID" beside it does not.
    const std::string long_name = std::string(250, 'a') + ".png";
    try {
        check_output_path(path(long_name));
        ADD_FAILURE() << "no error";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("file name too long"), std::string::npos) << e.what();
    }
    // A name whose temporary file fits is written.
    const std::string fits = std::string(200, 'a') + ".png";
    EXPECT_NO_THROW(check_output_path(path(fits)));
    write_image(path(fits), 2, 1, kPixels);
    EXPECT_TRUE(fs::is_regular_file(path(fits)));
}

TEST_F(ImageOutput, ReplacingAnImageIsAtomicAndLeavesNoTemporaryFile) {
    write_image(path("a.png"), 2, 1, kPixels);
    write_image(path("a.png"), 2, 1, std::vector<float>(6, 0.25f));
    EXPECT_EQ(files_in_dir(), 1u);
    auto in = OIIO::ImageInput::open(path("a.png"));
    std::vector<uint8_t> back(6);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, back.data()));
    EXPECT_EQ(back[0], back[5]);
}

TEST_F(ImageOutput, FailedWriteLeavesNeitherTargetNorTemporary) {
    // A directory in the way of the rename: the write must fail cleanly.
    fs::create_directories(path("blocked.png"));
    fs::create_directories(path("blocked.png/x"));
    EXPECT_THROW(write_image(path("blocked.png"), 2, 1, kPixels), ImageError);
    EXPECT_EQ(files_in_dir(), 1u);  // just the blocking directory
}

}  // namespace
}  // namespace wt
