// Image files: the right encoding per extension, read back through the image I/O module
// (read_image), AOV layers and metadata, and no half-written or temporary files left behind by
// a failure.

#include <cmath>
#include <filesystem>
#include <unistd.h>

#include <gtest/gtest.h>

#include "core/film/image_output.h"
#include "core/image_io/image_input.h"

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

// 8-bit values of an image read back (read_image gives them as value / 255).
std::vector<int> bytes_of(const ImageData& image) {
    std::vector<int> bytes;
    for (float v : image.pixels) bytes.push_back(int(std::lround(v * 255.0f)));
    return bytes;
}

TEST_F(ImageOutput, ExrKeepsLinearFloatRadiance) {
    write_image(path("a.exr"), 2, 1, kPixels);
    const ImageData in = read_image(path("a.exr"));
    EXPECT_EQ(in.width, 2);
    EXPECT_EQ(in.height, 1);
    EXPECT_EQ(in.channels, (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(in.pixels, kPixels);  // 2.0 above white survives
    EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(ImageOutput, PngIsSrgbEncodedAndClamped) {
    write_image(path("a.png"), 2, 1, kPixels);
    const ImageData in = read_image(path("a.png"));
    EXPECT_EQ(in.channels.size(), 3u);
    const std::vector<int> back = bytes_of(in);
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
    const std::vector<int> back = bytes_of(read_image(path("a.png")));
    EXPECT_EQ(back[0], back[5]);
}

TEST_F(ImageOutput, FailedWriteLeavesNeitherTargetNorTemporary) {
    // A directory in the way of the rename: the write must fail cleanly.
    fs::create_directories(path("blocked.png"));
    fs::create_directories(path("blocked.png/x"));
    EXPECT_THROW(write_image(path("blocked.png"), 2, 1, kPixels), ImageError);
    EXPECT_EQ(files_in_dir(), 1u);  // just the blocking directory
}

const ImageMetadata kMetadata{64, 18446744073709551615ull, "0123456789abcdef", 1.5, "9.8.7"};

// The wavetrace: attributes, as text whatever their type in the file.
void expect_metadata_of_kMetadata(const ImageData& in) {
    EXPECT_EQ(in.attribute("wavetrace:spp"), "64");
    EXPECT_EQ(in.attribute("wavetrace:seed"), "18446744073709551615");
    EXPECT_EQ(in.attribute("wavetrace:scene_hash"), "0123456789abcdef");
    EXPECT_EQ(in.attribute("wavetrace:render_seconds"), "1.5");
    EXPECT_EQ(in.attribute("wavetrace:version"), "9.8.7");
}

TEST_F(ImageOutput, ExrHoldsTheLayersAfterTheBeautyAndTheMetadata) {
    const ImageChannels layers{{"albedo.R", "albedo.G", "albedo.B", "Z"}, {0.1f, 0.2f, 0.3f, 4.0f, 0.5f, 0.6f, 0.7f, INFINITY}};
    write_image(path("a.exr"), 2, 1, kPixels, &kMetadata, &layers);
    const ImageData in = read_image(path("a.exr"));
    ASSERT_EQ(in.channels.size(), 7u);
    for (const char* c : {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "Z"}) EXPECT_GE(in.channel_index(c), 0) << c;
    EXPECT_EQ(in.value("R", 1, 0), 2.0f);
    EXPECT_EQ(in.value("albedo.G", 0, 0), 0.2f);
    EXPECT_EQ(in.value("albedo.B", 1, 0), 0.7f);
    EXPECT_EQ(in.value("Z", 0, 0), 4.0f);
    EXPECT_EQ(in.value("Z", 1, 0), INFINITY);
    expect_metadata_of_kMetadata(in);
    EXPECT_EQ(in.attribute("Software"), "wavetrace 9.8.7");
}

TEST_F(ImageOutput, PngHoldsTheMetadataAsTextAndTheBeautyOnly) {
    const ImageChannels layers{{"Z"}, {4.0f, 5.0f}};
    write_image(path("a.png"), 2, 1, kPixels, &kMetadata, &layers);
    write_image(path("plain.png"), 2, 1, kPixels);
    const ImageData in = read_image(path("a.png"));
    EXPECT_EQ(in.channels, (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(bytes_of(in), bytes_of(read_image(path("plain.png"))));  // the pixels do not change with metadata
    expect_metadata_of_kMetadata(in);
}

TEST_F(ImageOutput, JpegHoldsTheMetadataInItsDescription) {
    write_image(path("a.jpg"), 2, 1, kPixels, &kMetadata);
    const ImageData in = read_image(path("a.jpg"));
    EXPECT_EQ(in.attribute("Software"), "wavetrace 9.8.7");
    EXPECT_EQ(in.attribute("ImageDescription"),
              "wavetrace 9.8.7: 64 spp, seed 18446744073709551615, scene hash 0123456789abcdef, rendered in 1.5 s");
}

TEST_F(ImageOutput, ReadingAMissingOrBrokenFileNamesIt) {
    try {
        read_image(path("none.exr"));
        FAIL() << "read a missing file";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("none.exr"), std::string::npos) << e.what();
    }
    std::FILE* f = std::fopen(path("broken.exr").c_str(), "wb");
    std::fputs("not an image", f);
    std::fclose(f);
    EXPECT_THROW(read_image(path("broken.exr")), ImageError);
}

TEST_F(ImageOutput, LayersOfTheWrongSizeAreRefused) {
    const ImageChannels layers{{"Z"}, {4.0f}};
    EXPECT_THROW(write_image(path("a.exr"), 2, 1, kPixels, &kMetadata, &layers), ImageError);
    EXPECT_EQ(files_in_dir(), 0u);
}

}  // namespace
}  // namespace wt
