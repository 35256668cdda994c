// Caustics of the listed lights, which light paths alone carry (no camera path can reach a
// delta light through a mirror): the mirror caustic of mirror_caustic.h with its area light
// replaced by a point light, a spot or a directional light, against the floor's irradiance from
// the light's mirror image in closed form; the photons' flux on the floor against the same; and
// a scene lit by listed lights alone light-traced by default, the same bits for any schedule.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "kernels/caustics/light_path.h"
#include "lights_test_scenes.h"
#include "mirror_caustic.h"
#include "render_helpers.h"

namespace wt {
namespace {

using test::MirrorCaustic;
constexpr double kPiD = 3.14159265358979323846;
constexpr double kIntensity = 4.0, kIrradiance = 2.0;
constexpr double kConeDegrees = 100.0, kBlend = 0.5;
// The directional light travels along (1, 0, 1/2) / |.|: it enters under the mirror past the
// floor's edge at x = -6 and lights the floor, through the mirror, over -2 <= x < 2 (the
// reflected ray falls 2 in z over 4 in x), at incidence cos = (1/2) / sqrt(5/4).
const glm::vec3 kSunDirection(1.0f, 0.0f, 0.5f);
const double kSunCos = 0.5 / std::sqrt(1.25);

enum class Kind { point, spot, directional };
const char* name(Kind k) { return k == Kind::point ? "point" : k == Kind::spot ? "spot" : "directional"; }

double spot_falloff(double cos_angle) { return test::spot_falloff(cos_angle, kConeDegrees, kBlend); }

// The mirror caustic's floor and ceiling mirror (no area light), lit by one listed light at
// z = 1 (the spot pointing up), its image in the mirror at z = 3.
SceneDescription listed_caustic(Kind kind, int spp, uint64_t seed, CausticPaths caustics) {
    SceneDescription d = MirrorCaustic().scene(spp, seed, caustics);
    d.meshes.pop_back();  // the area light
    if (kind == Kind::point) d.lights = {test::point_light({0, 0, 1}, glm::vec3(float(kIntensity)))};
    if (kind == Kind::spot)
        d.lights = {test::spot_light({0, 0, 1}, {0, 0, 1}, glm::vec3(float(kIntensity)), float(kConeDegrees), float(kBlend))};
    if (kind == Kind::directional) d.lights = {test::directional_light(kSunDirection, glm::vec3(float(kIrradiance)), 0.0f)};
    return d;
}

// The floor's irradiance at x through the mirror: from the image point (0, 0, 3), I cos / d^2
// (the spot's falloff at the angle the reflected ray left its axis, which is the image ray's
// from -z); from the sun, E cos inside its strip. Times the mirror's reflectance.
double caustic_irradiance(Kind kind, const glm::dvec3& x) {
    if (kind == Kind::directional)
        return x.x >= -2.0 && x.x < 2.0 ? MirrorCaustic::reflectance * kIrradiance * kSunCos : 0.0;
    const glm::dvec3 to_image = glm::dvec3(0, 0, 3) - x;
    const double d2 = glm::dot(to_image, to_image), cos_floor = to_image.z / std::sqrt(d2);
    const double falloff = kind == Kind::spot ? spot_falloff(cos_floor) : 1.0;
    return MirrorCaustic::reflectance * kIntensity * falloff * cos_floor / d2;
}

// Whether the caustic is smooth about x: away from the sun's strip edges and the view's horizon.
bool usable(Kind kind, const glm::dvec3& x) {
    if (std::fabs(x.x) > 5 || std::fabs(x.y) > 5) return false;
    return kind != Kind::directional || std::fabs(x.x) < 1.8;
}

struct Block {
    int x0, y0;
    double analytic = 0.0;
    std::vector<double> rendered;
};
constexpr int kBlock = 6, kSub = 6, kSeeds = 12;
constexpr double kT = 5.45;  // two-sided Student-t, 1e-4 per block, 11 degrees of freedom

// Light tracing's splats (the light paths' whole part of the image) over blocks of floor,
// against the analytic radiance rho / pi E, within the seeds' Student-t bound.
void expect_light_traced_caustic(Kind kind) {
    const SceneDescription d0 = listed_caustic(kind, 16, 0, CausticPaths::light_tracing);
    std::vector<Block> blocks;
    for (int by = 0; by < d0.settings.height; by += kBlock)
        for (int bx = 0; bx < d0.settings.width; bx += kBlock) {
            Block b{bx, by, 0.0, {}};
            bool ok = true;
            for (int j = 0; j < kBlock * kBlock * kSub * kSub && ok; ++j) {
                const int pixel = j / (kSub * kSub), sub = j % (kSub * kSub);
                const glm::dvec3 eye(d0.camera.eye);
                const glm::dvec3 dir = test::view_direction(d0, bx + pixel % kBlock + (sub % kSub + 0.5) / kSub,
                                                            by + pixel / kBlock + (sub / kSub + 0.5) / kSub);
                if (!(dir.z < 0.0)) { ok = false; break; }
                const glm::dvec3 x = eye + (-eye.z / dir.z) * dir;
                ok = usable(kind, x);
                b.analytic += MirrorCaustic::rho / kPiD * caustic_irradiance(kind, x);
            }
            if (!ok) continue;
            b.analytic /= double(kBlock * kBlock * kSub * kSub);
            blocks.push_back(b);
        }
    ASSERT_GE(blocks.size(), 4u) << name(kind);
    for (int s = 0; s < kSeeds; ++s) {
        // The sun's paths mostly miss the gap under the mirror: more of them.
        SceneDescription d = listed_caustic(kind, kind == Kind::directional ? 32 : 16, uint64_t(1000 + s), CausticPaths::light_tracing);
        d.settings.estimator.light_paths_per_pixel = kind == Kind::spot ? 8.0f : kind == Kind::point ? 32.0f : 64.0f;
        const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 2);
        for (Block& b : blocks) {
            double sum = 0.0;
            for (int y = b.y0; y < b.y0 + kBlock; ++y)
                for (int x = b.x0; x < b.x0 + kBlock; ++x) sum += r.film.pixel_splat_mean(uint32_t(y * d.settings.width + x)).y;
            b.rendered.push_back(sum / (kBlock * kBlock));
        }
    }
    for (const Block& b : blocks) {
        double mean = 0.0, var = 0.0;
        for (double v : b.rendered) mean += v / kSeeds;
        for (double v : b.rendered) var += (v - mean) * (v - mean) / (kSeeds - 1);
        const double se = std::sqrt(var / kSeeds);
        EXPECT_NEAR(mean, b.analytic, kT * se + 1e-3 * b.analytic)
            << name(kind) << ", block at (" << b.x0 << ", " << b.y0 << "): relative error " << mean / b.analytic - 1.0;
        EXPECT_LT(kT * se, 0.1 * b.analytic) << name(kind) << ": too noisy to see a 10 % error";
    }
}

TEST(ListedLightCaustics, LightTracingMatchesThePointLightsMirrorImage) { expect_light_traced_caustic(Kind::point); }
TEST(ListedLightCaustics, LightTracingMatchesTheSpotsMirrorImageWithItsFalloff) { expect_light_traced_caustic(Kind::spot); }
TEST(ListedLightCaustics, LightTracingMatchesTheDirectionalLightThroughTheMirror) {
    expect_light_traced_caustic(Kind::directional);
}

// The photons' flux into a floor region (photons on the floor after the mirror, vertex 2) from
// many light paths, against the analytic flux: for the point light into a disk of radius a
// about the origin, R 2 pi I (1 - 3 / sqrt(9 + a^2)) (the image's solid angle of the disk); for
// the spot that solid angle weighted by its falloff, R 2 pi I * integral of falloff(c) dc over
// [3 / sqrt(9 + a^2), 1]; for the sun into the square |x|, |y| < 1, R E cos * 4. The photon
// powers are what the photon maps hold (per light path of a sample), so this checks the light
// paths' start and the photons' weights together.
void expect_photon_flux(Kind kind) {
    SceneDescription d = listed_caustic(kind, 1, 7, CausticPaths::photons);
    d.settings.max_bounces = 4;  // a photon needs a vertex after it: vertex 2 + 1 < max_bounces
    d.settings.width = d.settings.height = 100;
    d.settings.estimator.light_paths_per_pixel = kind == Kind::directional ? 160.0f : 20.0f;
    const Scene scene = build_scene(d);
    ASSERT_TRUE(scene.merges_photons) << name(kind);
    const LightPathTracer tracer(scene, nullptr, true);
    const uint64_t n = light_paths_per_sample(scene.settings);
    const double a = 2.0;
    const auto inside = [&](const glm::vec3& p) {
        return kind == Kind::directional ? std::fabs(p.x) < 1.0f && std::fabs(p.y) < 1.0f : double(glm::dot(glm::vec2(p), glm::vec2(p))) < a * a;
    };
    double sum = 0.0, sum2 = 0.0;
    RayCounts counts;
    std::vector<CameraSplat> splats;
    PhotonList photons;
    for (uint64_t i = 0; i < n; ++i) {
        photons.clear();
        tracer.trace(i, 0, counts, splats, nullptr, &photons);
        double path = 0.0;
        for (const Photon& p : photons)
            if (p.vertex == 2 && std::fabs(p.position.z) < 1e-4f && inside(p.position)) path += double(p.power.y) * double(n);
        sum += path, sum2 += path * path;
    }
    const double mean = sum / double(n), se = std::sqrt(std::max(0.0, sum2 / double(n) - mean * mean) / double(n));
    double expected = 0.0;
    const double c0 = 3.0 / std::sqrt(9.0 + a * a);
    if (kind == Kind::point) expected = MirrorCaustic::reflectance * 2.0 * kPiD * kIntensity * (1.0 - c0);
    if (kind == Kind::spot) {
        double integral = 0.0;
        const int steps = 100000;
        for (int k = 0; k < steps; ++k) integral += spot_falloff(c0 + (1.0 - c0) * (k + 0.5) / steps) * (1.0 - c0) / steps;
        expected = MirrorCaustic::reflectance * 2.0 * kPiD * kIntensity * integral;
    }
    if (kind == Kind::directional) expected = MirrorCaustic::reflectance * kIrradiance * kSunCos * 4.0;
    EXPECT_NEAR(mean, expected, 5.0 * se + 1e-4 * expected) << name(kind) << ": relative error " << mean / expected - 1.0;
    EXPECT_LT(5.0 * se, 0.05 * expected) << name(kind) << ": too noisy to see a 5 % error";
}

TEST(ListedLightCaustics, PhotonFluxMatchesThePointLightsMirrorImage) { expect_photon_flux(Kind::point); }
TEST(ListedLightCaustics, PhotonFluxMatchesTheSpotsMirrorImageWithItsFalloff) { expect_photon_flux(Kind::spot); }
TEST(ListedLightCaustics, PhotonFluxMatchesTheDirectionalLightThroughTheMirror) { expect_photon_flux(Kind::directional); }

// The environment seen through glass from a diffuse floor is the light paths' once they start
// at the environment (and the sun's, which escapes the same way): the camera paths must leave
// an escaped ray after a specular bounce to them, or it is counted twice. A glass ball on a
// floor under a constant sky and a sun with an angle: the image's mean over seeds, light-traced
// and path-traced, within 5 standard errors of their difference.
TEST(ListedLightCaustics, EnvironmentAndSunThroughGlassAreCountedOnce) {
    const auto image_means = [](CausticPaths caustics) {
        std::vector<double> means;
        for (int s = 0; s < 12; ++s) {
            SceneDescription d = test::lit_plane(0.5f, 6.0f, 3.0f, 40.0f, 64);
            d.camera.eye = {0.0f, -3.0f, 2.5f};
            d.camera.look_at = {0.0f, 0.0f, 0.3f};
            d.camera.up = {0.0f, 0.0f, 1.0f};
            d.settings.width = d.settings.height = 16;
            d.settings.seed = uint64_t(100 + s);
            d.settings.estimator.caustics = caustics;
            d.settings.estimator.light_paths_per_pixel = 4.0f;
            Material glass;
            glass.name = "glass";
            glass.type = MaterialType::glass;
            d.materials.push_back(glass);
            d.spheres = {Sphere{{0.0f, 0.0f, 0.8f}, 0.8f, 1}};
            d.lights = {test::constant_environment(glm::vec3(1.0f)),
                        test::directional_light({0.3f, 0.2f, -1.0f}, glm::vec3(3.0f), 20.0f)};
            const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 2);
            double sum = 0.0;
            for (uint32_t p = 0; p < uint32_t(d.settings.width * d.settings.height); ++p) sum += r.film.pixel_mean(p).y;
            means.push_back(sum / double(d.settings.width * d.settings.height));
        }
        return means;
    };
    const auto stats = [](const std::vector<double>& v) {
        double mean = 0.0, var = 0.0;
        for (double x : v) mean += x / double(v.size());
        for (double x : v) var += (x - mean) * (x - mean) / double(v.size() - 1);
        return std::pair<double, double>(mean, var / double(v.size()));
    };
    const auto [path, path_var] = stats(image_means(CausticPaths::path));
    const auto [traced, traced_var] = stats(image_means(CausticPaths::light_tracing));
    const double se = std::sqrt(path_var + traced_var);
    EXPECT_NEAR(traced, path, 5.0 * se) << "light tracing " << traced << ", path tracing " << path;
    // Counted twice, the light through the ball adds about 6 % to this image.
    EXPECT_LT(5.0 * se, 0.03 * path) << "too noisy to see a 3 % difference: se " << std::sqrt(path_var) << " (path), " << std::sqrt(traced_var) << " (light tracing)";
}

// A scene lit by listed lights alone, with a mirror: photons by default (the caustics default
// counts these lights), nothing without a specular surface, and the same bits for any thread
// count, schedule, kernel and integrator under light tracing and photons.
TEST(ListedLightCaustics, ListedLightsAloneAreLightTracedByDefaultAndTheSameBitsForAnySchedule) {
    SceneDescription d = listed_caustic(Kind::spot, 4, 3, EstimatorSettings().caustics);
    d.lights.push_back(test::point_light({1, 1, 1.5f}, glm::vec3(1.0f)));
    d.lights.push_back(test::directional_light(kSunDirection, glm::vec3(0.5f), 3.0f));
    d.lights.push_back(test::environment_light(test::test_environment_map(), 0.2f));
    EXPECT_TRUE(build_scene(d).light_traces_caustics);
    EXPECT_TRUE(build_scene(d).merges_photons);
    SceneDescription diffuse = d;
    diffuse.materials[1] = diffuse.materials[0];
    EXPECT_FALSE(build_scene(diffuse).light_traces_caustics);
    for (CausticPaths c : {CausticPaths::light_tracing, CausticPaths::photons}) {
        SCOPED_TRACE(name_of(c));
        d.settings.estimator.caustics = c;
        const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 1);
        EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
        EXPECT_GT(r.result.counts.light_paths, 0u);
        test::expect_same_film_for_any_schedule(d, r.film);
    }
}

}  // namespace
}  // namespace wt
