// AOVs: albedo, normal and depth on scenes whose answers are known (a plane at a known distance,
// a plane seen in a mirror, nothing at all), the same bits from both integrators and any thread
// count, the beauty image untouched by them, and the variance and sample count from the film.

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/film/aov.h"
#include "render_helpers.h"
#include "test_scenes.h"

namespace wt {
namespace {

const AovSelection kAll = parse_aov_list("all");

Material lambertian(const char* name, glm::vec3 albedo) {
    Material m;
    m.name = name;
    m.albedo = albedo;
    return m;
}

// A square in the plane x = `x`, spanning y in [y0, y1] and z in [-20, 20].
TriangleMesh square_at_x(float x, float y0, float y1, uint32_t material) {
    TriangleMesh mesh;
    mesh.vertices = {{x, y0, -20}, {x, y1, -20}, {x, y1, 20}, {x, y0, 20}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    mesh.material = material;
    return mesh;
}

// The camera at the origin looking along +x (screen right is -y), 16x16, no lights: only the AOVs matter.
SceneDescription camera_looking_along_x() {
    SceneDescription d;
    d.camera.eye = glm::vec3(0.0f);
    d.camera.look_at = glm::vec3(1, 0, 0);
    d.camera.fov_degrees = 60.0f;
    d.settings.width = 16;
    d.settings.height = 16;
    d.settings.spp = 4;
    d.settings.shadow_rays = 1;
    return d;
}

Film render_with(const SceneDescription& d, const AovSelection& aovs, Integrator integrator, int threads = 2) {
    const Scene scene = build_scene(d);
    RenderOptions options;
    options.integrator = integrator;
    options.threads = threads;
    options.aovs = aovs;
    Film film = test::film_for(scene, aovs);
    render(scene, options, film);
    return film;
}

float at(const ImageChannels& image, const std::string& channel, uint32_t pixel) {
    const auto it = std::find(image.names.begin(), image.names.end(), channel);
    if (it == image.names.end()) throw std::invalid_argument("no channel " + channel);
    return image.values[pixel * image.names.size() + std::size_t(it - image.names.begin())];
}

class AovIntegrators : public ::testing::TestWithParam<Integrator> {};

// A plane facing the camera 3 units away on the right half of the image, nothing on the left.
TEST_P(AovIntegrators, PlaneAtAKnownDistance) {
    SceneDescription d = camera_looking_along_x();
    d.materials = {lambertian("wall", {0.2f, 0.4f, 0.6f})};
    d.meshes = {square_at_x(3.0f, -20.0f, 0.0f, 0)};
    const ImageChannels aovs = resolve_aovs(render_with(d, kAll, GetParam()), kAll);
    for (uint32_t y = 0; y < 16; ++y) {
        for (uint32_t x = 9; x < 16; ++x) {  // right half, away from the plane's edge at the centre
            const uint32_t p = y * 16 + x;
            EXPECT_NEAR(at(aovs, "albedo.R", p), 0.2f, 1e-6f);
            EXPECT_NEAR(at(aovs, "albedo.G", p), 0.4f, 1e-6f);
            EXPECT_NEAR(at(aovs, "albedo.B", p), 0.6f, 1e-6f);
            // Facing the camera, whichever way the square is wound.
            EXPECT_NEAR(at(aovs, "N.R", p), -1.0f, 1e-6f);
            EXPECT_NEAR(at(aovs, "N.G", p), 0.0f, 1e-6f);
            EXPECT_NEAR(at(aovs, "N.B", p), 0.0f, 1e-6f);
            // Along the view axis, not along the ray: the same 3 at the corners as in the middle.
            EXPECT_NEAR(at(aovs, "Z", p), 3.0f, 3e-6f) << "pixel " << x << "," << y;
            EXPECT_EQ(at(aovs, "samples.Y", p), 4.0f);
        }
        for (uint32_t x = 0; x < 7; ++x) {  // left half: nothing there
            const uint32_t p = y * 16 + x;
            EXPECT_EQ(at(aovs, "albedo.G", p), 0.0f);
            EXPECT_EQ(at(aovs, "N.R", p), 0.0f);
            EXPECT_EQ(at(aovs, "Z", p), std::numeric_limits<float>::infinity());
            EXPECT_EQ(at(aovs, "samples.Y", p), 4.0f);
        }
    }
}

// A mirror 2 units ahead shows a wall 3 units behind the camera: the AOVs are the wall's (its
// albedo tinted by the mirror's reflectance, its normal), the depth is the mirror's.
TEST_P(AovIntegrators, WhatAMirrorShows) {
    SceneDescription d = camera_looking_along_x();
    Material mirror;
    mirror.name = "mirror";
    mirror.type = MaterialType::mirror;
    mirror.reflectance = {0.5f, 0.8f, 1.0f};
    d.materials = {mirror, lambertian("wall", {0.2f, 0.4f, 0.6f})};
    d.meshes = {square_at_x(2.0f, -20.0f, 20.0f, 0), square_at_x(-3.0f, -40.0f, 40.0f, 1)};
    d.meshes[1].vertices = {{-3, -40, -40}, {-3, 40, -40}, {-3, 40, 40}, {-3, -40, 40}};
    const ImageChannels aovs = resolve_aovs(render_with(d, kAll, GetParam()), kAll);
    for (uint32_t p = 0; p < 256; ++p) {
        EXPECT_NEAR(at(aovs, "albedo.R", p), 0.5f * 0.2f, 1e-6f);
        EXPECT_NEAR(at(aovs, "albedo.G", p), 0.8f * 0.4f, 1e-6f);
        EXPECT_NEAR(at(aovs, "albedo.B", p), 1.0f * 0.6f, 1e-6f);
        EXPECT_NEAR(at(aovs, "N.R", p), 1.0f, 1e-6f);  // the wall faces the mirror: +x
        EXPECT_NEAR(at(aovs, "N.G", p), 0.0f, 1e-6f);
        EXPECT_NEAR(at(aovs, "Z", p), 2.0f, 2e-6f);
    }
}

// A mirror that shows nothing: the albedo and normal of nothing, the mirror's depth.
TEST_P(AovIntegrators, AMirrorShowingNothing) {
    SceneDescription d = camera_looking_along_x();
    Material mirror;
    mirror.name = "mirror";
    mirror.type = MaterialType::mirror;
    d.materials = {mirror};
    d.meshes = {square_at_x(2.0f, -20.0f, 20.0f, 0)};
    const ImageChannels aovs = resolve_aovs(render_with(d, kAll, GetParam()), kAll);
    for (uint32_t p = 0; p < 256; ++p) {
        EXPECT_EQ(at(aovs, "albedo.R", p), 0.0f);
        EXPECT_EQ(at(aovs, "N.R", p), 0.0f);
        EXPECT_NEAR(at(aovs, "Z", p), 2.0f, 2e-6f);
    }
}

// A pane of glass (two parallel faces 0.1 apart) between a red wall ahead and a blue wall
// behind the camera, seen at near-normal incidence: each face reflects R = 0.04 (Schlick at
// normal incidence, IOR 1.5), so a path reaches the red wall with probability
// T = (1 - R)^2 (1 + R^2 + R^4 + ...) = (1 - R) / (1 + R), the blue one otherwise, and the
// albedo and normal average to that Fresnel blend of the two walls'.
TEST_P(AovIntegrators, ThroughGlassTheFresnelBlendOfWhatIsBehindAndReflected) {
    SceneDescription d = camera_looking_along_x();
    d.camera.fov_degrees = 10.0f;
    d.settings.spp = 64;
    Material glass;
    glass.name = "glass";
    glass.type = MaterialType::glass;
    glass.ior = 1.5f;
    d.materials = {glass, lambertian("red", {0.5f, 0.0f, 0.0f}), lambertian("blue", {0.0f, 0.0f, 0.5f})};
    // Outward normals: -x for the near face, +x for the far one.
    d.meshes = {square_at_x(2.0f, 20.0f, -20.0f, 0), square_at_x(2.1f, -20.0f, 20.0f, 0),
                square_at_x(5.0f, -20.0f, 20.0f, 1), square_at_x(-3.0f, -20.0f, 20.0f, 2)};
    const Film film = render_with(d, kAll, GetParam());
    const ImageChannels aovs = resolve_aovs(film, kAll);
    const double r = 0.04, t = (1 - r) / (1 + r);
    double red = 0, blue = 0, normal_x = 0;
    for (uint32_t p = 0; p < 256; ++p) {
        red += at(aovs, "albedo.R", p) / 256.0;
        blue += at(aovs, "albedo.B", p) / 256.0;
        normal_x += at(aovs, "N.R", p) / 256.0;
        EXPECT_NEAR(at(aovs, "Z", p), 2.0f, 2e-6f);  // the glass's
    }
    // Each of the 16384 samples picks a wall: sd of the red mean 0.5 sqrt(T (1 - T) / 16384) = 0.001.
    const double sd = 0.5 * std::sqrt(t * (1 - t) / (256.0 * 64.0));
    EXPECT_NEAR(red, 0.5 * t, 4.5 * sd);
    EXPECT_NEAR(blue, 0.5 * (1 - t), 4.5 * sd);
    // Every path reaches one of the walls, but Russian roulette (from the fourth vertex) ends
    // some of those that bounce inside the pane and weights up the others: 0.5 on average only.
    EXPECT_NEAR(red + blue, 0.5, 4.5 * sd);
    EXPECT_NEAR(normal_x, (1 - t) - t, 9 * sd);  // red faces -x, blue +x
}

INSTANTIATE_TEST_SUITE_P(BothIntegrators, AovIntegrators, ::testing::Values(Integrator::wavefront, Integrator::reference),
                         [](const auto& info) { return info.param == Integrator::wavefront ? "wavefront" : "reference"; });

TEST(Aov, BothIntegratorsAndAnyThreadCountGiveTheSameBits) {
    const SceneDescription d = test::hexroom(24, 24, 4);
    const Film wavefront = render_with(d, kAll, Integrator::wavefront, 2);
    EXPECT_TRUE(wavefront == render_with(d, kAll, Integrator::reference, 2));
    EXPECT_TRUE(wavefront == render_with(d, kAll, Integrator::wavefront, 1));
    EXPECT_TRUE(wavefront == render_with(d, kAll, Integrator::wavefront, 3));
}

// Every estimator has its own shade loop with AOVs (stage_shade_aovs.cpp): the same bits from
// both integrators, and the beauty that estimator gives without them.
TEST(Aov, EveryEstimatorRecordsThemAlike) {
    for (SamplerKind sampler : {SamplerKind::independent, SamplerKind::stratified, SamplerKind::sobol})
        for (LightSampling lights : {LightSampling::nee, LightSampling::mis})
            for (float clamp : {0.0f, 2.0f}) {
                SceneDescription d = test::hexroom(16, 16, 2);
                d.settings.estimator = {sampler, lights, clamp};
                const Film wavefront = render_with(d, kAll, Integrator::wavefront);
                EXPECT_TRUE(wavefront == render_with(d, kAll, Integrator::reference))
                    << name_of(sampler) << " " << name_of(lights) << " clamp " << clamp;
                const Film without = render_with(d, AovSelection{}, Integrator::wavefront);
                for (uint32_t p = 0; p < wavefront.pixel_total(); ++p)
                    ASSERT_EQ(wavefront.pixel_sum(p), without.pixel_sum(p)) << name_of(sampler) << " " << name_of(lights);
                const ImageChannels aovs = resolve_aovs(wavefront, kAll);
                EXPECT_GT(at(aovs, "albedo.R", 8 * 16 + 8), 0.0f);  // the middle of the room: something was recorded
            }
}

// The hexroom through glass spheres and a mirror wall: the albedo stays within [0, 1], and
// where a glass sphere is seen it shows what is behind or reflected (not zero, not the glass).
TEST(Aov, AlbedoStaysInTheUnitRange) {
    const ImageChannels aovs = resolve_aovs(render_with(test::hexroom(32, 32, 8), kAll, Integrator::wavefront), kAll);
    for (uint32_t p = 0; p < 32 * 32; ++p)
        for (const char* c : {"albedo.R", "albedo.G", "albedo.B"}) {
            EXPECT_GE(at(aovs, c, p), 0.0f);
            EXPECT_LE(at(aovs, c, p), 1.0f);
        }
}

TEST(Aov, TheBeautyImageIsTheSameWithAndWithout) {
    const SceneDescription d = test::hexroom(24, 24, 4);
    for (Integrator integrator : {Integrator::wavefront, Integrator::reference}) {
        const Film with = render_with(d, kAll, integrator);
        const Film without = render_with(d, AovSelection{}, integrator);
        for (uint32_t p = 0; p < with.pixel_total(); ++p) {
            ASSERT_EQ(with.pixel_count(p), without.pixel_count(p));
            ASSERT_EQ(with.raw_sums()[p * with.channels_per_pixel()], without.raw_sums()[p * without.channels_per_pixel()]);
            ASSERT_EQ(with.pixel_sum(p), without.pixel_sum(p));
            ASSERT_EQ(with.pixel_sample_variance(p), without.pixel_sample_variance(p));
        }
    }
}

TEST(Aov, VarianceIsOfThePixelMeanAndSamplesTheCount) {
    const AovSelection film_only = parse_aov_list("variance,samples");
    EXPECT_FALSE(film_only.needs_path_data());
    EXPECT_TRUE(aov_film_channels(film_only).empty());  // nothing per sample
    const Film film = render_with(test::hexroom(16, 16, 8), film_only, Integrator::wavefront);
    const ImageChannels aovs = resolve_aovs(film, film_only);
    EXPECT_EQ(aovs.names, (std::vector<std::string>{"variance.R", "variance.G", "variance.B", "samples.Y"}));
    double total = 0.0;
    for (uint32_t p = 0; p < film.pixel_total(); ++p) {
        const glm::dvec3 v = film.pixel_sample_variance(p) / 8.0;
        EXPECT_EQ(at(aovs, "variance.R", p), float(v.x));
        EXPECT_EQ(at(aovs, "variance.B", p), float(v.z));
        EXPECT_EQ(at(aovs, "samples.Y", p), 8.0f);
        total += v.x;
    }
    EXPECT_GT(total, 0.0);  // a noisy image, so the test above compares something
}

TEST(Aov, AFilmWithoutTheChannelsIsRefused) {
    const SceneDescription d = test::hexroom(8, 8, 1);
    const Scene scene = build_scene(d);
    RenderOptions options;
    options.aovs = kAll;
    Film film(8, 8);
    EXPECT_THROW(render(scene, options, film), std::invalid_argument);
}

TEST(Aov, ListsAreParsedAndBadNamesNamed) {
    const AovSelection s = parse_aov_list("depth,albedo");
    EXPECT_TRUE(s.depth && s.albedo);
    EXPECT_FALSE(s.normal || s.variance || s.samples);
    const AovSelection all = parse_aov_list("all");
    EXPECT_TRUE(all.albedo && all.normal && all.depth && all.variance && all.samples);
    for (const char* bad : {"", "albedo,", ",albedo", "albedo,,depth", "Albedo", "albedo normal", "z"}) {
        try {
            parse_aov_list(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("choose from albedo, normal, depth, variance, samples"), std::string::npos);
        }
    }
}

}  // namespace
}  // namespace wt
