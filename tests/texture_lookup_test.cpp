// Texture lookups against hand-computed values on tiny images: texel centres exact, bilinear
// between them, every wrap mode, sRGB decoding against the formula, each mip level the box
// filter of the one before (odd sizes included), and levels of detail between two levels.

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "core/textures/srgb.h"
#include "core/geometry/texture_coordinates.h"
#include "core/textures/texture_lookup.h"
#include "texture_test_images.h"

namespace wt {
namespace {

// A data (linear) texture whose texel (x, y) has red x + 10 y, green 1, blue y, alpha 0.5:
// values stored as given, so the expectations below are the formula's.
TextureImage ramp(int width, int height, TextureWrap wrap = TextureWrap::repeat, bool srgb = false) {
    return test::texture_of(
        width, height, [](int x, int y) { return glm::vec4(0.01f * float(x + 10 * y), 1.0f, 0.1f * float(y), 0.5f); }, wrap, srgb);
}

float red(int x, int y) { return 0.01f * float(x + 10 * y); }

glm::vec2 centre(int x, int y, int width, int height) { return {(float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)}; }

TEST(TextureLookup, TexelCentresAreExact) {
    const MipPyramid t(ramp(4, 8));
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 4; ++x) {
            const glm::vec4 c = texture_lookup(t, centre(x, y, 4, 8), 0.0f);
            EXPECT_EQ(c.x, red(x, y)) << x << "," << y;
            EXPECT_EQ(c.z, 0.1f * float(y));
            EXPECT_EQ(c.w, 0.5f);
        }
}

TEST(TextureLookup, BilinearBetweenCentres) {
    const MipPyramid t(ramp(4, 4, TextureWrap::clamp));
    // A quarter of the way from texel (1, 2)'s centre to (2, 3)'s in x and three quarters in y.
    const glm::vec2 uv((1.5f + 0.25f) / 4.0f, (2.5f + 0.75f) / 4.0f);
    const float expected = 0.75f * 0.25f * red(1, 2) + 0.25f * 0.25f * red(2, 2) + 0.75f * 0.75f * red(1, 3) +
                           0.25f * 0.75f * red(2, 3);
    EXPECT_NEAR(texture_lookup(t, uv, 0.0f).x, expected, 1e-6f);
    // The image's centre: the mean of the four middle texels.
    EXPECT_NEAR(texture_lookup(t, {0.5f, 0.5f}, 0.0f).x, 0.25f * (red(1, 1) + red(2, 1) + red(1, 2) + red(2, 2)), 1e-6f);
}

TEST(TextureLookup, WrapModes) {
    // Texel indices.
    EXPECT_EQ(wrap_texel(-1, 4, TextureWrap::repeat), 3);
    EXPECT_EQ(wrap_texel(4, 4, TextureWrap::repeat), 0);
    EXPECT_EQ(wrap_texel(-1, 4, TextureWrap::clamp), 0);
    EXPECT_EQ(wrap_texel(4, 4, TextureWrap::clamp), 3);
    EXPECT_EQ(wrap_texel(-1, 4, TextureWrap::mirror), 0);
    EXPECT_EQ(wrap_texel(4, 4, TextureWrap::mirror), 3);
    EXPECT_EQ(wrap_texel(5, 4, TextureWrap::mirror), 2);
    EXPECT_EQ(wrap_texel(8, 4, TextureWrap::mirror), 0);
    // Coordinates: repeat shifts by whole images, mirror reflects every other one, clamp holds the edge.
    const MipPyramid repeat(ramp(4, 4, TextureWrap::repeat)), mirror(ramp(4, 4, TextureWrap::mirror)),
        clamp(ramp(4, 4, TextureWrap::clamp));
    const glm::vec2 uv = centre(1, 2, 4, 4);
    EXPECT_EQ(texture_lookup(repeat, uv + glm::vec2(3.0f, -2.0f), 0.0f).x, red(1, 2));
    EXPECT_EQ(texture_lookup(mirror, glm::vec2(2.0f - uv.x, uv.y), 0.0f).x, red(1, 2));       // u reflected about 1
    EXPECT_EQ(texture_lookup(mirror, glm::vec2(1.0f + uv.x, uv.y), 0.0f).x, red(2, 2));       // 1 + u reads 1 - u
    EXPECT_EQ(texture_lookup(clamp, glm::vec2(7.5f, uv.y), 0.0f).x, red(3, 2));
    EXPECT_EQ(texture_lookup(clamp, glm::vec2(-3.0f, -1e30f), 0.0f).x, red(0, 0));
    // Across the seam, repeat blends the last texel with the first: u = 0 is halfway between them.
    EXPECT_NEAR(texture_lookup(repeat, glm::vec2(0.0f, uv.y), 0.0f).x, 0.5f * (red(3, 2) + red(0, 2)), 1e-6f);
    // Coordinates that would overflow a texel index, or are not numbers, read the image.
    for (float u : {1e30f, -1e30f, NAN, INFINITY}) {
        const float r = texture_lookup(repeat, glm::vec2(u, 0.3f), 0.0f).x;
        EXPECT_TRUE(r >= 0.0f && r <= red(3, 3)) << u;
    }
}

TEST(TextureLookup, SrgbDecodedByTheFormula) {
    for (float c : {0.0f, 0.02f, 0.04045f, 0.2f, 0.5f, 0.8f, 1.0f}) {
        const double expected = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
        EXPECT_NEAR(srgb_to_linear(c), expected, 1e-6 * std::max(1.0, expected)) << c;
    }
    EXPECT_NEAR(srgb_to_linear(0.5f), 0.2140411f, 1e-6f);
    // A colour texture is decoded when built, alpha left linear; a data texture is not.
    const MipPyramid colour(ramp(2, 2, TextureWrap::repeat, true)), data(ramp(2, 2));
    EXPECT_EQ(colour.level(0).at(1, 1).x, srgb_to_linear(red(1, 1)));
    EXPECT_EQ(colour.level(0).at(1, 1).w, 0.5f);
    EXPECT_EQ(data.level(0).at(1, 1).x, red(1, 1));
}

TEST(TextureLookup, MipLevelsAreTheBoxFilter) {
    const MipPyramid t(ramp(4, 4));
    ASSERT_EQ(t.level_count(), 3u);  // 4x4, 2x2, 1x1
    const MipLevel& one = t.level(1);
    ASSERT_EQ(one.width, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            EXPECT_NEAR(one.at(x, y).x,
                        0.25f * (red(2 * x, 2 * y) + red(2 * x + 1, 2 * y) + red(2 * x, 2 * y + 1) + red(2 * x + 1, 2 * y + 1)),
                        1e-6f);
    double mean = 0.0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) mean += red(x, y) / 16.0;
    EXPECT_NEAR(t.level(2).at(0, 0).x, mean, 1e-6);
    // Odd sizes: 5x3 goes to 2x1, each texel covering 2.5 x 3 source texels, the middle column
    // shared half and half.
    const MipPyramid odd(ramp(5, 3));
    ASSERT_EQ(odd.level(1).width, 2);
    ASSERT_EQ(odd.level(1).height, 1);
    for (int x = 0; x < 2; ++x) {
        double sum = 0.0;
        for (int y = 0; y < 3; ++y)
            for (int k = 0; k < 3; ++k) sum += (k == (x == 0 ? 2 : 0) ? 0.5 : 1.0) * red(2 * x + k, y);
        EXPECT_NEAR(odd.level(1).at(x, 0).x, sum / 7.5, 1e-6) << x;
    }
    EXPECT_EQ(odd.level_count(), 3u);  // 5x3, 2x1, 1x1
    // The memory: every level's texels.
    EXPECT_EQ(t.bytes(), (16u + 4u + 1u) * sizeof(glm::vec4));
}

TEST(TextureLookup, LevelOfDetailBlendsTwoLevels) {
    const MipPyramid t(ramp(4, 4, TextureWrap::clamp));
    const glm::vec2 uv(0.3f, 0.6f);
    const float l0 = bilinear(t.level(0), TextureWrap::clamp, TextureWrap::clamp, uv).x;
    const float l1 = bilinear(t.level(1), TextureWrap::clamp, TextureWrap::clamp, uv).x;
    const float l2 = t.level(2).at(0, 0).x;
    EXPECT_EQ(texture_lookup(t, uv, 0.0f).x, l0);
    EXPECT_EQ(texture_lookup(t, uv, -5.0f).x, l0);
    EXPECT_EQ(texture_lookup(t, uv, NAN).x, l0);
    EXPECT_NEAR(texture_lookup(t, uv, 0.25f).x, 0.75f * l0 + 0.25f * l1, 1e-6f);
    EXPECT_EQ(texture_lookup(t, uv, 2.0f).x, l2);
    EXPECT_EQ(texture_lookup(t, uv, INFINITY).x, l2);
}

TEST(TextureLookup, TexelsClampedToUnitAndNanToZero) {
    auto texels = std::make_shared<TextureTexels>();
    texels->width = 2, texels->height = 1;
    texels->rgba = {glm::vec4(NAN, -1.0f, 3.0f, INFINITY), glm::vec4(0.25f)};
    TextureImage image;
    image.texels = texels;
    image.srgb = false;
    const MipPyramid t(image);
    EXPECT_EQ(t.level(0).at(0, 0), glm::vec4(0.0f, 0.0f, 1.0f, 1.0f));
    EXPECT_EQ(t.level(0).at(1, 0), glm::vec4(0.25f));
}

TEST(TextureLookup, TransformIsTranslateRotateScale) {
    // KHR_texture_transform: uv' = T R S uv with R = [cos sin; -sin cos].
    TextureImage image = ramp(4, 4);
    image.scale = glm::vec2(2.0f, 1.0f);
    image.rotation = 1.5707963267948966f;
    image.offset = glm::vec2(0.5f, 0.0f);
    const MipPyramid t(image);
    // S (0.25, 0.5) = (0.5, 0.5); R turns it to (0.5, -0.5); T moves it to (1, -0.5).
    const glm::vec2 uv = t.transformed({0.25f, 0.5f});
    EXPECT_NEAR(uv.x, 1.0f, 1e-6f);
    EXPECT_NEAR(uv.y, -0.5f, 1e-6f);
    // Twice the texels per unit of u: half a level more detail needed.
    EXPECT_FLOAT_EQ(t.log2_texel_scale(), 0.5f * std::log2(16.0f) + 0.5f);
    // Without a transform the coordinates are the same bits.
    const MipPyramid plain(ramp(4, 4));
    const glm::vec2 odd(0.123456f, -7.654321f);
    EXPECT_EQ(plain.transformed(odd), odd);
    EXPECT_EQ(plain.log2_texel_scale(), 2.0f);
}

TEST(TextureCoordinates, InterpolatedAndTheirDensity) {
    // A right triangle of area 2 in the world mapped onto half the unit square (uv area 0.5),
    // and one of a mesh without coordinates, indexed as the triangles' positions are.
    TriangleSoA triangles;
    TextureCoordinateTable table;
    const float s = 2.0f;
    const uint32_t first = triangles.add_vertices({{0, 0, 0}, {s, 0, 0}, {0, s, 0}});
    table.add_vertices(3, {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}}, {}, {});
    triangles.push(first, first + 1, first + 2, 0);
    table.push_triangle({first, first + 1, first + 2}, 2.0f);
    const uint32_t second = triangles.add_vertices({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
    table.add_vertices(3, {}, {}, {});
    triangles.push(second, second + 2, second + 1, 0);
    table.push_triangle({second, second + 2, second + 1}, 0.5f);
    ASSERT_EQ(table.size(), 2u);
    const glm::vec2 uv = table.at(triangles, 0, 0.25f, 0.5f);
    EXPECT_FLOAT_EQ(uv.x, 0.25f);
    EXPECT_FLOAT_EQ(uv.y, 0.5f);
    EXPECT_FLOAT_EQ(table.log2_density(0), 0.5f * std::log2(0.25f));
    EXPECT_EQ(table.at(triangles, 1, 0.25f, 0.5f), glm::vec2(0.0f));
    EXPECT_EQ(table.log2_density(1), -INFINITY);  // no coordinates: level 0
    // Neither set 1 nor vertex tangents were given: none is stored, and they read as absent.
    EXPECT_EQ(table.at(triangles, 0, 0.25f, 0.5f, 1), glm::vec2(0.0f));
    EXPECT_EQ(table.log2_density(0, 1), -INFINITY);
    EXPECT_FALSE(table.vertex_tangents(triangles, 0));
    EXPECT_EQ(table.bytes(), 6 * sizeof(glm::vec2) + 2 * sizeof(float));
    // The tangent frame solved from the edges and coordinates: dP/du = +x s, -dP/dv = -y s.
    const TextureCoordinateTable::TangentFrame f = table.tangent_frame(triangles, 0);
    EXPECT_EQ(f.tangent, glm::vec3(s, 0, 0));
    EXPECT_EQ(f.bitangent, glm::vec3(0, -s, 0));
    EXPECT_EQ(table.tangent_frame(triangles, 1).tangent, glm::vec3(0.0f));  // no coordinates: no frame
}

}  // namespace
}  // namespace wt
