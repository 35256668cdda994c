// Textured scenes in the renderer: a uniform texture renders the bits of the untextured
// material it equals; a texture seen from far reads the averaged level its ray cones pick (the
// bits of its mean), and seen from near its texels; a half-black, half-white texture gives each
// half's radiance; and a textured scene's image is the same bits for every thread count,
// schedule, integrator and ISA.

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "core/materials/microfacet_material.h"
#include "kernels/memory_estimate.h"
#include "lights_test_scenes.h"
#include "render_helpers.h"
#include "statistics.h"
#include "test_scenes.h"
#include "texture_test_images.h"

namespace wt {
namespace {

using test::texture_of;

TEST(TextureRender, UniformTextureIsTheBitsOfItsValue) {
    // The hexroom with every diffuse albedo doubled and a constant 0.5 texture on it: the
    // textured loop (material_at, the run-time material tests) must compute what the plain
    // room's loop computes, bit for bit, on walls (parallelograms) and spheres alike.
    for (CausticPaths caustics : {CausticPaths::path, CausticPaths::photons}) {
        SceneDescription plain = test::hexroom(24, 16, 4);
        plain.settings.estimator.caustics = caustics;
        SceneDescription textured = plain;
        textured.textures.push_back(texture_of(4, 4, [](int, int) { return glm::vec4(0.5f); }));
        int textured_materials = 0;
        for (Material& m : textured.materials)
            if (!m.is_specular() && !m.is_microfacet() && !m.is_emissive()) {
                m.albedo *= 2.0f;
                m.color_texture = 0;
                ++textured_materials;
            }
        ASSERT_GT(textured_materials, 0);
        ASSERT_TRUE(build_scene(textured).has_textures());
        const Film expected = test::render_film(plain, Integrator::wavefront).film;
        EXPECT_TRUE(expected == test::render_film(textured, Integrator::wavefront).film);
        EXPECT_TRUE(expected == test::render_film(textured, Integrator::reference).film);
    }
}

TEST(TextureRender, MetallicRoughnessTextureIsTheBitsOfItsValues) {
    // Principled spheres in the hexroom with metallic and roughness 1 times a constant texture of
    // green 0.5 and blue 0.25 (glTF's channels for them): the bits of metallic 0.25, roughness 0.5.
    SceneDescription plain = test::hexroom(24, 16, 4);
    const uint32_t first = uint32_t(plain.materials.size());
    plain.materials.push_back(principled_material(glm::vec3(0.9f, 0.6f, 0.3f), 0.25f, 0.5f, 1.5f, glm::vec3(0.0f)));
    plain.materials.push_back(principled_material(glm::vec3(0.2f, 0.4f, 0.8f), 0.25f, 0.5f, 1.5f, glm::vec3(0.0f)));
    for (std::size_t i = 0; i < plain.spheres.size(); ++i) plain.spheres[i].material = first + uint32_t(i % 2);
    SceneDescription textured = plain;
    textured.textures.push_back(texture_of(2, 2, [](int, int) { return glm::vec4(0.0f, 0.5f, 0.25f, 1.0f); }));
    for (uint32_t k = first; k < first + 2; ++k) {
        Material& m = textured.materials[k];
        ASSERT_EQ(m.type, MaterialType::principled);
        m.metallic = m.roughness = 1.0f;
        m.metallic_roughness_texture = 0;
    }
    const Film expected = test::render_film(plain, Integrator::wavefront).film;
    EXPECT_TRUE(expected == test::render_film(textured, Integrator::wavefront).film);
    EXPECT_TRUE(expected == test::render_film(textured, Integrator::reference).film);
}

// A square of side `side` in the z = 0 plane facing +z, its coordinates spanning [0, 1]^2
// (v = 0 at y = +side/2, the image's top row), under a constant environment of radiance 1,
// seen from height `height` straight down with a 40 degree pinhole.
SceneDescription textured_square(float side, float camera_height, const TextureImage& texture) {
    SceneDescription d;
    Material m;
    m.name = "textured";
    m.albedo = glm::vec3(1.0f);
    m.color_texture = 0;
    d.materials.push_back(m);
    d.textures.push_back(texture);
    TriangleMesh mesh;
    const float h = 0.5f * side;
    mesh.vertices = {{-h, -h, 0.0f}, {h, -h, 0.0f}, {h, h, 0.0f}, {-h, h, 0.0f}};
    mesh.uvs = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    d.meshes.push_back(mesh);
    d.lights = {test::constant_environment(glm::vec3(1.0f))};
    d.camera.eye = glm::vec3(0.0f, 0.0f, camera_height);
    d.camera.look_at = glm::vec3(0.0f);
    d.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    d.camera.fov_degrees = 40.0f;
    d.settings.width = d.settings.height = 16;
    d.settings.spp = 16;
    return d;
}

TextureImage checkerboard(int n) {
    return texture_of(n, n, [](int x, int y) { return glm::vec4(float((x + y) % 2)); });
}

TEST(TextureRender, RayConesPickTheLevelAFarTextureNeeds) {
    // 64 texels across 8 units seen from 10 away: a pixel's cone is some 3.6 texels wide at the
    // square (level 1.9 and more), where the checkerboard's levels are all exactly 0.5. Camera
    // rays' hits then reflect as an untextured 0.5 albedo does; the bounces after them escape.
    const SceneDescription far = textured_square(8.0f, 10.0f, checkerboard(64));
    SceneDescription grey = far;
    grey.materials[0].albedo = glm::vec3(0.5f);
    grey.materials[0].color_texture = -1;
    EXPECT_TRUE(test::render_film(far, Integrator::wavefront).film == test::render_film(grey, Integrator::wavefront).film);
    // From 2 away a pixel covers less than a texel: level 0, the checkerboard's own black and
    // white texels, which the grey square's image is not.
    const SceneDescription near = textured_square(8.0f, 2.0f, checkerboard(64));
    SceneDescription near_grey = near;
    near_grey.materials[0] = grey.materials[0];
    const Film near_film = test::render_film(near, Integrator::wavefront).film;
    EXPECT_FALSE(near_film == test::render_film(near_grey, Integrator::wavefront).film);
    // And that image is the same bits for every schedule, integrator and ISA.
    test::expect_same_film_for_any_schedule(near, near_film);
}

TEST(TextureRender, HalfBlackHalfWhiteGivesEachHalfItsRadiance) {
    // Black left half, white right half, seen from 2 away (the square fills the view, level 0):
    // a pixel whose footprint is well inside the black half is exactly 0; inside the white half
    // it reflects the environment's 1 (albedo 1, no other surface), within its noise.
    const SceneDescription d =
        textured_square(8.0f, 2.0f, texture_of(8, 8, [](int x, int) { return glm::vec4(x < 4 ? 0.0f : 1.0f); }, TextureWrap::clamp));
    const Film film = test::render_film(d, Integrator::wavefront).film;
    std::vector<double> white;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const uint32_t pixel = uint32_t(y * 16 + x);
            // The view spans 2 * 2 tan(20 deg) = 1.46 units of the 8-unit square about its centre,
            // the texture's centre, 0.091 a pixel column: bilinear blends the middle unit
            // (x in [-0.5, 0.5], uv 0.4375 to 0.5625), so columns 0-1 see black alone, 14-15 white.
            if (x <= 1) {
                EXPECT_EQ(film.pixel_mean(pixel).x, 0.0) << x << "," << y;
            }
            if (x >= 14) white.push_back(film.pixel_mean(pixel).x);
        }
    // Their mean against 1, within five standard errors of the pixels' spread.
    double mean = 0.0, square = 0.0;
    for (double w : white) mean += w / double(white.size());
    for (double w : white) square += (w - mean) * (w - mean) / double(white.size() - 1);
    EXPECT_NEAR(mean, 1.0, 5.0 * std::sqrt(square / double(white.size())) + 1e-3);
    EXPECT_GT(mean, 0.5);
}

TEST(TextureRender, FlatNormalMapIsNoNormalMapAndATiltedOneShades) {
    // A flat texel (0.5, 0.5, 1): the same bits as the square without a normal map.
    SceneDescription plain = textured_square(8.0f, 2.0f, checkerboard(64));
    SceneDescription flat = plain;
    flat.textures.push_back(texture_of(2, 2, [](int, int) { return glm::vec4(0.5f, 0.5f, 1.0f, 1.0f); }));
    flat.materials[0].normal_texture = 1;
    const Film expected = test::render_film(plain, Integrator::wavefront).film;
    EXPECT_TRUE(expected == test::render_film(flat, Integrator::wavefront).film);
    EXPECT_TRUE(expected == test::render_film(flat, Integrator::reference).film);
    // Tilted by 45 degrees about the tangent: the image changes, is finite, and is the same bits
    // for every schedule and both integrators.
    SceneDescription tilted = flat;
    tilted.textures[1] = texture_of(2, 2, [](int, int) { return glm::vec4(0.5f + 0.5f * 0.70710678f, 0.5f, 0.5f + 0.5f * 0.70710678f, 1.0f); });
    const test::RenderedFilm rendered = test::render_film(tilted, Integrator::wavefront);
    EXPECT_FALSE(expected == rendered.film);
    EXPECT_EQ(rendered.result.counts.nonfinite_samples, 0u);
    test::expect_same_film_for_any_schedule(tilted, rendered.film);
}

TEST(TextureCoordinates, TangentFrameFromTheCoordinates) {
    // textured_square's triangles: u grows with +x, v with -y, so dP/du = +x / 8 units ... and
    // glTF's bitangent, -dP/dv, is +y.
    const Scene scene = build_scene(textured_square(8.0f, 2.0f, checkerboard(4)));
    ASSERT_EQ(scene.texture_coordinates.size(), scene.triangles.size());
    for (std::size_t i = 0; i < scene.texture_coordinates.size(); ++i) {
        const TextureCoordinateTable::TangentFrame f = scene.texture_coordinates.tangent_frame(scene.triangles, i);
        EXPECT_NEAR(f.tangent.x, 8.0f, 1e-5f);
        EXPECT_NEAR(f.tangent.y, 0.0f, 1e-5f);
        EXPECT_NEAR(f.bitangent.y, 8.0f, 1e-5f);
        EXPECT_NEAR(f.bitangent.x, 0.0f, 1e-5f);
    }
}

TEST(TextureRender, MemoryEstimateCountsTheTextures) {
    const SceneDescription d = textured_square(8.0f, 10.0f, checkerboard(64));
    const Scene scene = build_scene(d);
    const MemoryEstimate e = estimate_render_memory(scene, RenderOptions{});
    // 64^2 + 32^2 + ... + 1 texels of 16 bytes, and the two triangles' coordinates.
    std::size_t texels = 0;
    for (int side = 64; side >= 1; side /= 2) texels += std::size_t(side) * std::size_t(side);
    EXPECT_EQ(scene.textures[0].bytes(), texels * 16);
    EXPECT_EQ(e.textures, double(texels * 16 + scene.texture_coordinates.bytes()));
    // A coordinate pair per vertex, a density per triangle.
    EXPECT_GE(scene.texture_coordinates.bytes(), scene.triangles.vertex_count() * sizeof(glm::vec2) + 2u * sizeof(float));
    EXPECT_GE(e.total(), e.to_allocate() + e.geometry + e.textures);
    EXPECT_NE(texture_memory_line(scene).find("textures: 1 image, "), std::string::npos) << texture_memory_line(scene);
    // Without a textured material neither the levels nor the coordinates exist.
    SceneDescription grey = d;
    grey.materials[0].color_texture = -1;
    const Scene untextured = build_scene(grey);
    EXPECT_FALSE(untextured.has_textures());
    EXPECT_TRUE(untextured.texture_coordinates.empty());
    EXPECT_EQ(estimate_render_memory(untextured, RenderOptions{}).textures, 0.0);
}

}  // namespace
}  // namespace wt
