// EXR and PNG files written through OpenEXR and libpng (core/image_io/direct_image_output.h)
// against the same images written by the image I/O module's OpenImageIO writers, which they
// replace. Read back through the module, both files give the same size, channels, values and
// attributes. That alone would not see an attribute under another name in the file (OpenImageIO
// reads `comments` and a text chunk `ImageDescription` both as ImageDescription), so the files
// themselves are compared too: the EXR headers' attributes (names, types, text values) through
// OpenEXR, and the PNG files' chunks, listed by a reader of this file's own. Also what only the
// direct writers do: refuse the wrong pixel type, and name the file when it cannot be written.

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <gtest/gtest.h>

#include "core/image_io/direct_image_output.h"
#include "core/image_io/image_input.h"
#include "core/image_io/image_module.h"

namespace wt {
namespace {

namespace fs = std::filesystem;

class DirectImageOutput : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("wavetrace-direct-image-test-" + std::to_string(getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

// The attributes render_command writes (image_output.cpp), in OpenImageIO's names.
const std::vector<WtImageAttribute> kAttributes = {
    {"oiio:ColorSpace", WT_ATTRIBUTE_STRING, "Linear", 0, 0.0f},
    {"Software", WT_ATTRIBUTE_STRING, "wavetrace 9.8.7", 0, 0.0f},
    {"ImageDescription", WT_ATTRIBUTE_STRING, "wavetrace 9.8.7: 64 spp, seed 3, scene hash 0123456789abcdef", 0, 0.0f},
    {"wavetrace:spp", WT_ATTRIBUTE_INT, nullptr, 64, 0.0f},
    {"wavetrace:seed", WT_ATTRIBUTE_STRING, "18446744073709551615", 0, 0.0f},
    {"wavetrace:render_seconds", WT_ATTRIBUTE_FLOAT, nullptr, 0, 1.25f},
};

// The attributes read back but DateTime, the time of writing, which differs between the two
// files; it is checked for being there.
std::map<std::string, std::string> attributes_but_date(const ImageData& image) {
    std::map<std::string, std::string> kept(image.attributes.begin(), image.attributes.end());
    kept.erase("DateTime");
    return kept;
}

void expect_same_image(const ImageData& direct, const ImageData& module) {
    EXPECT_EQ(direct.width, module.width);
    EXPECT_EQ(direct.height, module.height);
    EXPECT_EQ(direct.channels, module.channels);
    ASSERT_EQ(direct.pixels.size(), module.pixels.size());
    for (std::size_t i = 0; i < direct.pixels.size(); ++i) {
        // Bit for bit, NaN and infinity included (the writers must not touch a value).
        EXPECT_EQ(std::memcmp(&direct.pixels[i], &module.pixels[i], sizeof(float)), 0)
            << "value " << i << ": " << direct.pixels[i] << " against " << module.pixels[i];
    }
    EXPECT_EQ(attributes_but_date(direct), attributes_but_date(module));
}

// Each attribute of an EXR file's header: its type, and its value if it is text but the date.
std::map<std::string, std::string> exr_header(const std::string& path) {
    Imf::InputFile file(path.c_str());
    std::map<std::string, std::string> attributes;
    for (auto it = file.header().begin(); it != file.header().end(); ++it) {
        std::string text = it.attribute().typeName();
        if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()); s && std::string(it.name()) != "capDate")
            text += " " + s->value();
        attributes[it.name()] = text;
    }
    return attributes;
}

// A PNG file's chunks in order, as their types, a text chunk as "tEXt key=value", every IDAT
// chunk and OpenImageIO's oFFs (a position of 0, 0: no offset) left out. Read by hand from the
// format's layout (length, type, data, CRC), sharing no code with libpng.
std::vector<std::string> png_chunks(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::string> chunks;
    if (bytes.size() < 8 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return {"not a PNG file"};
    for (std::size_t at = 8; at + 12 <= bytes.size();) {
        const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + at);
        const std::size_t length = std::size_t(b[0]) << 24 | std::size_t(b[1]) << 16 | std::size_t(b[2]) << 8 | b[3];
        const std::string type = bytes.substr(at + 4, 4);
        if (at + 12 + length > bytes.size()) return {"truncated chunk " + type};
        std::string data = bytes.substr(at + 8, length);
        const std::size_t key_end = data.find('\0');
        if (type == "tEXt" && key_end != std::string::npos) chunks.push_back("tEXt " + data.replace(key_end, 1, "="));
        else if (type != "IDAT" && type != "oFFs") chunks.push_back(type);
        at += 12 + length;
    }
    return chunks;
}

// `image` written to `direct` by a direct writer and to `module` through the image module.
void write_both(WtImageToWrite image, void (*write)(const WtImageToWrite&), const std::string& direct,
                const std::string& module) {
    image.path = direct.c_str();
    write(image);
    image.path = module.c_str();
    char error[1024];
    ASSERT_EQ(image_module().write_image(&image, error, sizeof error), 0) << error;
}

TEST_F(DirectImageOutput, ExrReadsBackAsTheModulesExr) {
    // 5x3, seven channels as the AOVs name them, values across float's range: zero of both
    // signs, denormals, the largest finite, infinity, NaN.
    const std::vector<const char*> names = {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "Z"};
    const int width = 5, height = 3, channels = int(names.size());
    std::vector<float> pixels;
    const float specials[] = {0.0f, -0.0f, std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max(),
                              INFINITY, std::numeric_limits<float>::quiet_NaN(), 1e-30f, 0.18f};
    for (int i = 0; i < width * height * channels; ++i)
        pixels.push_back(i % 5 == 0 ? specials[(i / 5) % 8] : 0.37f * float(i) - 3.0f);
    const WtImageToWrite image{nullptr, width, height, channels, names.data(), WT_PIXEL_FLOAT, pixels.data(),
                               kAttributes.data(), int(kAttributes.size())};
    const std::string direct = path("direct.exr"), module = path("module.exr");
    write_both(image, &write_exr, direct, module);
    const ImageData a = read_image(direct), b = read_image(module);
    expect_same_image(a, b);
    EXPECT_EQ(a.channels.size(), names.size());
    EXPECT_EQ(a.value("Z", 4, 2), pixels.back());
    EXPECT_EQ(a.attribute("ImageDescription"), std::string(kAttributes[2].string_value));
    EXPECT_EQ(a.attribute("wavetrace:spp"), "64");
    EXPECT_TRUE(a.attribute("DateTime").has_value());
    EXPECT_TRUE(b.attribute("DateTime").has_value());

    const std::map<std::string, std::string> header = exr_header(direct);
    EXPECT_EQ(header, exr_header(module));
    EXPECT_EQ(header.at("comments"), std::string("string ") + kAttributes[2].string_value);  // EXR's own name
    EXPECT_EQ(header.at("capDate"), "string");
    EXPECT_EQ(header.at("wavetrace:spp"), "int");
    EXPECT_EQ(header.count("oiio:ColorSpace"), 0u);
}

TEST_F(DirectImageOutput, PngReadsBackAsTheModulesPng) {
    const std::vector<const char*> names = {"R", "G", "B"};
    const int width = 7, height = 4;
    std::vector<unsigned char> pixels;
    for (int i = 0; i < width * height * 3; ++i) pixels.push_back((unsigned char)(i * 37 % 256));
    std::vector<WtImageAttribute> attributes = kAttributes;
    attributes[0].string_value = "sRGB";
    attributes[3] = {"wavetrace:spp", WT_ATTRIBUTE_STRING, "64", 0, 0.0f};  // PNG text: render_command writes text
    attributes[5] = {"wavetrace:render_seconds", WT_ATTRIBUTE_STRING, "1.25", 0, 0.0f};
    const WtImageToWrite image{nullptr, width, height, 3, names.data(), WT_PIXEL_UINT8, pixels.data(), attributes.data(),
                         int(attributes.size())};
    const std::string direct = path("direct.png"), module = path("module.png");
    write_both(image, &write_png, direct, module);
    const ImageData a = read_image(direct), b = read_image(module);
    expect_same_image(a, b);
    EXPECT_EQ(a.pixels[1], 37.0f / 255.0f);
    EXPECT_EQ(a.attribute("ImageDescription"), std::string(kAttributes[2].string_value));
    EXPECT_EQ(a.attribute("wavetrace:seed"), "18446744073709551615");
    EXPECT_EQ(a.attribute("oiio:ColorSpace"), "sRGB");

    const std::vector<std::string> chunks = png_chunks(direct);
    EXPECT_EQ(chunks, png_chunks(module));
    ASSERT_GE(chunks.size(), 5u);
    EXPECT_EQ(chunks[0], "IHDR");
    EXPECT_EQ(chunks[2], "sRGB");  // after its gAMA fallback, as the PNG specification orders them
    EXPECT_NE(std::find(chunks.begin(), chunks.end(), std::string("tEXt Description=") + kAttributes[2].string_value),
              chunks.end());  // PNG's own keyword
    EXPECT_EQ(chunks.back(), "IEND");
}

// One RGB pixel of each type, and images of it to write to `exr` and `png` as each type.
struct OnePixel {
    std::vector<const char*> names = {"R", "G", "B"};
    std::vector<float> floats = std::vector<float>(3, 0.5f);
    std::vector<unsigned char> bytes = std::vector<unsigned char>(3, 128);
    WtImageToWrite floats_to(const std::string& path) const {
        return {path.c_str(), 1, 1, 3, names.data(), WT_PIXEL_FLOAT, floats.data(), nullptr, 0};
    }
    WtImageToWrite bytes_to(const std::string& path) const {
        return {path.c_str(), 1, 1, 3, names.data(), WT_PIXEL_UINT8, bytes.data(), nullptr, 0};
    }
};

void expect_refused_naming_the_file(const WtImageToWrite& image, void (*write)(const WtImageToWrite&)) {
    try {
        write(image);
        ADD_FAILURE() << image.path << " was written";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find(image.path), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(image.path));
}

TEST_F(DirectImageOutput, TheWrongPixelTypeIsRefusedNamingTheFile) {
    const OnePixel pixel;
    const std::string exr = path("a.exr"), png = path("a.png");
    expect_refused_naming_the_file(pixel.bytes_to(exr), &write_exr);
    expect_refused_naming_the_file(pixel.floats_to(png), &write_png);
    // The right types are written.
    write_exr(pixel.floats_to(exr));
    write_png(pixel.bytes_to(png));
    EXPECT_EQ(read_image(exr).pixels, pixel.floats);
    EXPECT_EQ(read_image(png).pixels, std::vector<float>(3, 128.0f / 255.0f));
}

TEST_F(DirectImageOutput, AFileThatCannotBeCreatedIsNamed) {
    const OnePixel pixel;
    expect_refused_naming_the_file(pixel.floats_to(path("missing/a.exr")), &write_exr);
    expect_refused_naming_the_file(pixel.bytes_to(path("missing/a.png")), &write_png);
}

}  // namespace
}  // namespace wt
