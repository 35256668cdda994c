// Renders lit by the "lights" list against analytic answers, wavefront against reference bit
// for bit, and light tracing against plain path tracing where both are unbiased.

#include <cmath>

#include <gtest/gtest.h>

#include "lights_test_scenes.h"
#include "render_helpers.h"
#include "statistics.h"

namespace wt {
namespace {

constexpr double kPiD = 3.14159265358979323846;

// Every pixel of `film` estimates `expected` (per channel): a z-test per pixel with the pooled
// per-sample variance (all pixels estimate the same value), a binomial allowance for chance,
// and the image mean against the pooled standard error.
void expect_every_pixel_near(const Film& film, const glm::dvec3& expected, int spp) {
    const int pixels = film.width() * film.height();
    glm::dvec3 pooled(0.0), image(0.0);
    for (uint32_t p = 0; p < uint32_t(pixels); ++p) pooled += film.pixel_sample_variance(p), image += film.pixel_mean(p);
    pooled /= double(pixels);
    image /= double(pixels);
    const double z = test::normal_two_sided_quantile(1e-3);
    const int allowed = test::binomial_upper_bound(3 * pixels, 1e-3, 1e-6);
    int failures = 0;
    for (uint32_t p = 0; p < uint32_t(pixels); ++p)
        for (int c = 0; c < 3; ++c) {
            const double se = std::sqrt(pooled[c] / spp);
            failures += std::fabs(film.pixel_mean(p)[c] - expected[c]) > z * se + 1e-6 * expected[c];
        }
    EXPECT_LE(failures, allowed);
    for (int c = 0; c < 3; ++c) {
        const double se = std::sqrt(pooled[c] / (double(spp) * pixels));
        EXPECT_NEAR(image[c], expected[c], 4.5 * se + 1e-6 * expected[c]) << "channel " << c;
    }
}

struct EstimatorCase {
    const char* name;
    LightSampling light_sampling;
    Integrator integrator;
};

class ConstantEnvironment : public ::testing::TestWithParam<EstimatorCase> {};

// A convex Lambertian object in a constant environment L has no interreflection: every point
// reflects rho L. With nee only the light samples count the environment after the bounce, with
// mis both strategies weighted: either way the mean is rho L.
TEST_P(ConstantEnvironment, LambertianSphereShowsAlbedoTimesRadiance) {
    const glm::vec3 rho(0.5f, 0.25f, 0.8f), L(1.0f, 2.0f, 0.5f);
    SceneDescription d = test::sphere_filling_the_image(rho, 64);
    d.settings.estimator.light_sampling = GetParam().light_sampling;
    d.lights = {test::constant_environment(L)};
    const test::RenderedFilm r = test::render_film(d, GetParam().integrator);
    expect_every_pixel_near(r.film, glm::dvec3(rho * L), d.settings.spp);
    EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
}

TEST_P(ConstantEnvironment, RaysThatMissEverythingSeeTheEnvironment) {
    const glm::vec3 L(1.0f, 2.0f, 0.5f);
    SceneDescription d = test::sphere_filling_the_image(glm::vec3(0.5f), 4);
    d.settings.estimator.light_sampling = GetParam().light_sampling;
    d.camera.look_at = {0.0f, -4.0f, 1.0f};  // straight up, past the sphere
    d.lights = {test::constant_environment(L)};
    const test::RenderedFilm r = test::render_film(d, GetParam().integrator);
    for (uint32_t p = 0; p < uint32_t(d.settings.width * d.settings.height); ++p)
        EXPECT_EQ(glm::vec3(r.film.pixel_mean(p)), L) << "pixel " << p;
}

INSTANTIATE_TEST_SUITE_P(Estimators, ConstantEnvironment,
                         ::testing::Values(EstimatorCase{"nee_wavefront", LightSampling::nee, Integrator::wavefront},
                                           EstimatorCase{"mis_wavefront", LightSampling::mis, Integrator::wavefront},
                                           EstimatorCase{"nee_reference", LightSampling::nee, Integrator::reference},
                                           EstimatorCase{"mis_reference", LightSampling::mis, Integrator::reference}),
                         [](const auto& info) { return std::string(info.param.name); });

// Radiance of a Lambertian plane lit by a point light of intensity I at height h, at horizontal
// distance r: rho / pi * I h / (h^2 + r^2)^(3/2). The camera sees r up to `r_max`, so every
// sample lies between the values at r_max and at 0 (nothing else lights the plane).
void expect_point_lit_plane(const test::RenderedFilm& r, const SceneDescription& d, double rho, double I, double h,
                            double r_max) {
    const double at_centre = rho / kPiD * I / (h * h);
    const double at_edge = rho / kPiD * I * h / std::pow(h * h + r_max * r_max, 1.5);
    for (uint32_t p = 0; p < uint32_t(d.settings.width * d.settings.height); ++p) {
        const double v = r.film.pixel_mean(p).y;
        EXPECT_LE(v, at_centre * (1.0 + 1e-5)) << "pixel " << p;
        EXPECT_GE(v, at_edge * (1.0 - 1e-5)) << "pixel " << p;
    }
}

TEST(PointLight, PlaneBelowShowsRhoIOverPiHSquared) {
    const float rho = 0.6f, I = 5.0f, h = 2.0f;
    for (LightSampling ls : {LightSampling::nee, LightSampling::mis}) {
        SceneDescription d = test::lit_plane(rho, 100.0f, 2.0f * h, 1.0f, 8);
        d.settings.estimator.light_sampling = ls;
        d.lights = {test::point_light({0.0f, 0.0f, h}, glm::vec3(I))};
        const double r_max = 2.0 * h * std::tan(0.5 * kPiD / 180.0) * std::sqrt(2.0);  // the image's corner
        expect_point_lit_plane(test::render_film(d, Integrator::wavefront), d, rho, I, h, r_max);
        expect_point_lit_plane(test::render_film(d, Integrator::reference), d, rho, I, h, r_max);
    }
}

TEST(SpotLight, FullWithinItsInnerConeAndDarkOutsideItsOuterCone) {
    const float rho = 0.6f, I = 5.0f, h = 2.0f;
    const double r_max = 2.0 * h * std::tan(0.5 * kPiD / 180.0) * std::sqrt(2.0);
    SceneDescription d = test::lit_plane(rho, 100.0f, 2.0f * h, 1.0f, 8);
    d.lights = {test::spot_light({0.0f, 0.0f, h}, {0.0f, 0.0f, -1.0f}, glm::vec3(I), 60.0f, 0.5f)};
    expect_point_lit_plane(test::render_film(d, Integrator::wavefront), d, rho, I, h, r_max);
    // Tilted 45 degrees away, the plane below is outside its 60-degree cone: black.
    d.lights = {test::spot_light({0.0f, 0.0f, h}, {1.0f, 0.0f, -1.0f}, glm::vec3(I), 60.0f, 0.5f)};
    const test::RenderedFilm dark = test::render_film(d, Integrator::wavefront);
    for (uint32_t p = 0; p < uint32_t(d.settings.width * d.settings.height); ++p)
        EXPECT_EQ(dark.film.pixel_mean(p).y, 0.0) << "pixel " << p;
}

TEST(DirectionalLight, DeltaAndSunDiskGiveRhoEOverPiTimesCosine) {
    const float rho = 0.5f, E = 3.0f;
    const double cos_incidence = std::cos(30.0 * kPiD / 180.0);
    const glm::vec3 direction(std::sin(30.0 * kPiD / 180.0), 0.0f, -cos_incidence);
    for (float angle : {0.0f, 0.53f, 10.0f}) {
        for (LightSampling ls : {LightSampling::nee, LightSampling::mis}) {
            SceneDescription d = test::lit_plane(rho, 100.0f, 4.0f, 5.0f, 32);
            d.settings.estimator.light_sampling = ls;
            d.lights = {test::directional_light(direction, glm::vec3(E), angle)};
            const test::RenderedFilm r = test::render_film(d, Integrator::wavefront);
            // A cone of radiance E / (pi sin^2 a) about the direction: its irradiance on the
            // tilted plane is E cos(incidence), exactly, as long as the cone stays above the horizon.
            expect_every_pixel_near(r.film, glm::dvec3(rho / kPiD * E * cos_incidence), d.settings.spp);
            EXPECT_TRUE(r.film == test::render_film(d, Integrator::reference).film) << "angle " << angle;
        }
    }
}

// Everything at once: area light, map environment, point, spot and a sun, glass and a mirror
// (so light tracing or photons run for the area light), a rough conductor and a smooth mesh
// absent: the integrators, schedules, thread counts and kernels all give the same bits.
SceneDescription everything_scene(LightSampling ls, CausticPaths caustics) {
    SceneDescription d = test::lit_plane(0.7f, 6.0f, 5.0f, 50.0f, 4);
    d.camera.eye = {0.5f, -4.0f, 3.0f};
    d.camera.up = {0.0f, 0.0f, 1.0f};
    d.settings.width = d.settings.height = 16;
    d.settings.estimator.light_sampling = ls;
    d.settings.estimator.caustics = caustics;
    Material lamp;
    lamp.name = "lamp";
    lamp.emission = glm::vec3(8.0f);
    Material glass;
    glass.name = "glass";
    glass.type = MaterialType::glass;
    Material mirror;
    mirror.name = "mirror";
    mirror.type = MaterialType::mirror;
    Material rough;
    rough.name = "rough";
    rough.type = MaterialType::rough_conductor;
    rough.roughness = 0.4f;
    d.materials.push_back(lamp), d.materials.push_back(glass), d.materials.push_back(mirror), d.materials.push_back(rough);
    TriangleMesh light;
    light.vertices = {{-0.5f, -0.5f, 2.5f}, {-0.5f, 0.5f, 2.5f}, {0.5f, 0.5f, 2.5f}, {0.5f, -0.5f, 2.5f}};
    light.triangles = {{0, 1, 2}, {0, 2, 3}};
    light.material = 1;
    d.meshes.push_back(light);
    d.spheres = {Sphere{{0.0f, 0.0f, 0.8f}, 0.8f, 2}, Sphere{{1.6f, 0.5f, 0.5f}, 0.5f, 3}, Sphere{{-1.5f, 0.5f, 0.6f}, 0.6f, 4}};
    d.lights = {test::environment_light(test::test_environment_map(), 0.5f, 20.0f),
                test::point_light({1.5f, -1.0f, 2.0f}, glm::vec3(3.0f, 2.0f, 1.0f)),
                test::spot_light({-1.0f, -1.0f, 3.0f}, {0.3f, 0.3f, -1.0f}, glm::vec3(10.0f), 40.0f, 0.3f),
                test::directional_light({0.4f, 0.2f, -1.0f}, glm::vec3(1.0f, 0.9f, 0.7f), 2.0f)};
    return d;
}

TEST(ListedLights, SameBitsForEveryIntegratorScheduleAndThreadCount) {
    for (LightSampling ls : {LightSampling::nee, LightSampling::mis})
        for (CausticPaths c : {CausticPaths::path, CausticPaths::light_tracing, CausticPaths::photons}) {
            SCOPED_TRACE(testing::Message() << "mis " << (ls == LightSampling::mis) << " caustics " << int(c));
            const SceneDescription d = everything_scene(ls, c);
            const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 1);
            EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
            test::expect_same_film_for_any_schedule(d, r.film);
        }
}

// Light paths start at every light, and the camera paths leave them what they take over
// (escaped rays after a specular bounce included): light tracing and plain path tracing
// estimate the same image where both can find every path, i.e. without the delta lights, whose
// caustics only light paths find (lights_caustic_test.cpp): the area light, the map and the sun
// with an angle.
TEST(ListedLights, LightTracingAgreesWithPathTracing) {
    SceneDescription d = everything_scene(LightSampling::mis, CausticPaths::path);
    d.lights = {d.lights[0], d.lights[3]};
    ASSERT_EQ(d.lights[1].type, LightType::directional);
    d.settings.spp = 64;
    const Film path = test::render_film(d, Integrator::wavefront).film;
    d.settings.estimator.caustics = CausticPaths::light_tracing;
    const Scene scene = build_scene(d);
    ASSERT_TRUE(scene.light_traces_caustics);
    const Film traced = test::render_film(d, Integrator::wavefront).film;
    test::expect_films_agree(path, traced, [](uint32_t p) { return "pixel " + std::to_string(p); });
}

// nee and mis weigh the environment's two strategies differently, to the same answer.
TEST(ListedLights, NeeAndMisAgree) {
    SceneDescription d = everything_scene(LightSampling::nee, CausticPaths::path);
    d.settings.spp = 64;
    const Film nee = test::render_film(d, Integrator::wavefront).film;
    d.settings.estimator.light_sampling = LightSampling::mis;
    const Film mis = test::render_film(d, Integrator::wavefront).film;
    test::expect_films_agree(nee, mis, [](uint32_t p) { return "pixel " + std::to_string(p); });
}

}  // namespace
}  // namespace wt
