// Emission textures (glTF's emissiveTexture, a scene file's "emission": {"texture": ...}): the
// radiance seen directly is the factor times the decoded texel; a floor lit by a half-black,
// half-white textured light gets the quadrature value of that light from light samples, from
// BSDF samples (through the hit's texture lookup) and from both weighted by MIS, and not the
// untextured light's; light tracing and photons carry the texture from where their paths start;
// selection by power and the light tree weigh the texture's mean, with pick and pdf the same
// bits and the image unbiased against selection by area; and the image is the same bits for
// every schedule, integrator and ISA.

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/description/scene_hash.h"
#include "core/sampling/sampling.h"
#include "core/scene/material_at_hit.h"
#include "kernels/memory_estimate.h"
#include "mirror_caustic.h"
#include "render_helpers.h"
#include "texture_test_images.h"

namespace wt {
namespace {

using test::texture_of;

double srgb_decoded(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// A square light of side 2 s at height h, facing down (-z), centred above the origin, its
// texture coordinates u along +x and v along +y (u = (x + s) / 2s). Material 1 in `d`.
TriangleMesh downward_light(float s, float h) {
    TriangleMesh lamp;  // clockwise seen from above: facing down
    lamp.vertices = {{-s, -s, h}, {-s, s, h}, {s, s, h}, {s, -s, h}};
    lamp.uvs = {{0.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}};
    lamp.triangles = {{0, 1, 2}, {0, 2, 3}};
    lamp.material = 1;
    return lamp;
}

// Two texels, black then white, clamped: bilinear at level 0 reads clamp(2u - 0.5, 0, 1).
TextureImage black_then_white() {
    return texture_of(2, 1, [](int x, int) { return glm::vec4(float(x), float(x), float(x), 1.0f); }, TextureWrap::clamp);
}
double black_then_white_at(double u) { return std::min(1.0, std::max(0.0, 2.0 * u - 0.5)); }

TEST(EmissionTexture, LightSeenDirectlyIsTheFactorTimesTheDecodedTexel) {
    // A 4 x 4 sRGB texture on the light, seen from just below at texel centres through a 1 x 1
    // image of a tiny field of view (the ray cone picks level 0, and the pixel spans some 1e-8 of
    // the light, so its neighbours' share in the bilinear lookup is float rounding's size): the
    // pixel is the factor times the decoded texel, a bright one and a dark one.
    const glm::vec4 bright(0.9f, 0.5f, 0.1f, 1.0f), dark(0.05f, 0.02f, 0.01f, 1.0f);
    const glm::vec3 factor(3.0f, 2.0f, 5.0f);
    for (const auto& [ix, iy, texel] : {std::tuple{1, 2, bright}, std::tuple{3, 0, dark}}) {
        SceneDescription d;
        Material nothing, light;
        light.name = "light";
        light.emission = factor;
        light.emission_texture = 0;
        d.materials = {nothing, light};
        d.meshes = {downward_light(0.5f, 1.0f)};
        const int bx = ix, by = iy;
        const glm::vec4 chosen = texel;
        d.textures = {texture_of(4, 4, [&](int x, int y) { return x == bx && y == by ? chosen : glm::vec4(0.3f); },
                                 TextureWrap::repeat, /*srgb=*/true)};
        // The texel's centre: u = (ix + 0.5) / 4 is x = -0.5 + u, and v likewise y.
        const float x = -0.5f + (float(ix) + 0.5f) / 4.0f, y = -0.5f + (float(iy) + 0.5f) / 4.0f;
        d.camera.eye = {x, y, 0.99f};
        d.camera.look_at = {x, y, 1.0f};
        d.camera.up = {0.0f, 1.0f, 0.0f};
        d.camera.fov_degrees = 1e-4f;
        d.settings.width = d.settings.height = 1;
        d.settings.spp = 4;
        for (Integrator integrator : {Integrator::wavefront, Integrator::reference}) {
            const glm::dvec3 seen = test::render_film(d, integrator).film.pixel_mean(0);
            for (int c = 0; c < 3; ++c) {
                const double expected = double(factor[c]) * srgb_decoded(double(texel[c]));
                EXPECT_NEAR(seen[c], expected, 1e-4 * expected) << "texel " << ix << "," << iy << " channel " << c;
            }
        }
    }
}

// A floor (albedo rho, z = 0) lit by the downward light of side 1 at height 1 emitting
// Le times black_then_white, seen at floor point p through a 1 x 1 image of a tiny field of view.
// Only direct light reaches p: the light reflects nothing (albedo 0), and the floor is a plane.
struct FloorUnderTexturedLight {
    static constexpr float rho = 0.5f, le = 4.0f, s = 0.5f, h = 1.0f;
    static constexpr double px = 0.3;  // off centre, over the white half: a flipped texture is less
    // second_set: the texture reads TEXCOORD_1, which runs u the other way (u = (s - x) / 2s),
    // while TEXCOORD_0 stays as downward_light has it.
    SceneDescription scene(int spp, bool textured, bool second_set = false) const {
        SceneDescription d;
        Material floor, light;
        floor.name = "floor";
        floor.albedo = glm::vec3(rho);
        light.name = "light";
        light.emission = glm::vec3(le);
        if (textured) {
            light.emission_texture = 0;
            d.textures = {black_then_white()};
        }
        d.materials = {floor, light};
        d.meshes = {test::quad({-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}, 0), downward_light(s, h)};
        if (second_set) {
            d.textures[0].coordinate_set = 1;
            for (const glm::vec2& uv : d.meshes[1].uvs) d.meshes[1].second_uvs.push_back({1.0f - uv.x, uv.y});
        }
        d.camera.eye = glm::vec3(float(px) + 0.3f, 0.0f, 0.2f);
        d.camera.look_at = glm::vec3(float(px), 0.0f, 0.0f);
        d.camera.up = glm::vec3(0, 0, 1);
        d.camera.fov_degrees = 0.001f;
        d.settings.width = d.settings.height = 1;
        d.settings.spp = spp;
        d.settings.estimator.sampler = SamplerKind::independent;
        return d;
    }
    // rho / pi times the irradiance at p: the integral over the light of L cos cos / r^2, by the
    // midpoint rule on a grid whose cells' edges hold the texture's kinks (u = 1/4 and 3/4).
    static double expected(bool textured, bool second_set = false) {
        const int n = 400;
        double sum = 0.0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double u = (i + 0.5) / n, v = (j + 0.5) / n;
                const double x = -s + 2.0 * s * u - px, y = -s + 2.0 * s * v;
                const double r2 = x * x + y * y + double(h) * h;
                sum += (textured ? black_then_white_at(second_set ? 1.0 - u : u) : 1.0) * double(h) * double(h) / (r2 * r2);
            }
        const double irradiance = le * sum * (2.0 * s) * (2.0 * s) / (double(n) * n);
        return rho / M_PI * irradiance;
    }
};

// The renderer's estimate and its standard error.
struct Estimate {
    double mean, standard_error;
};

Estimate rendered(const SceneDescription& d) {
    const test::RenderedFilm r = test::render_film(d, Integrator::wavefront);
    EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
    return {r.film.pixel_mean(0).y, std::sqrt(r.film.pixel_sample_variance(0).y / d.settings.spp)};
}

// BSDF sampling alone, which the renderer has no switch for: cosine-weighted directions from the
// floor point, and each one that finds the light scores rho times the emission the hit reads
// through material_at (the renderer's hit lookup), at level 0 as a bounce's hit.
Estimate bsdf_sampling_alone(const Scene& scene, glm::vec3 p, int n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    double sum = 0.0, square = 0.0;
    std::optional<Material> scratch;
    for (int k = 0; k < n; ++k) {
        const glm::vec3 d = sample_cosine_hemisphere(uniform(rng), uniform(rng));  // about +z
        const float t = (FloorUnderTexturedLight::h - p.z) / d.z;
        const glm::vec3 q = p + t * d;
        double score = 0.0;
        if (std::fabs(q.x) < FloorUnderTexturedLight::s && std::fabs(q.y) < FloorUnderTexturedLight::s) {
            // The light's triangles (0, 1, 2) and (0, 2, 3) after the floor's parallelogram.
            for (uint32_t prim = 1; prim <= 2; ++prim) {
                const glm::vec3 a = scene.triangles.vertex0(prim), e1 = scene.triangles.edge1(prim),
                                e2 = scene.triangles.edge2(prim);
                // Barycentrics in the light's plane (z constant): a 2 x 2 solve.
                const glm::vec2 r(q.x - a.x, q.y - a.y);
                const float det = e1.x * e2.y - e1.y * e2.x;
                const float u = (r.x * e2.y - r.y * e2.x) / det, v = (e1.x * r.y - e1.y * r.x) / det;
                if (u < 0.0f || v < 0.0f || u + v > 1.0f) continue;
                Hit hit;
                hit.prim = prim, hit.t = t, hit.u = u, hit.v = v;
                const Ray ray{p, d};
                SurfacePoint surface = surface_at(scene, ray, hit);
                const Material& m = material_at(scene, hit, surface, ray, false, scratch);
                score = double(FloorUnderTexturedLight::rho) * (glm::dot(d, surface.normal) < 0.0f ? m.emission.y : 0.0f);
                break;
            }
        }
        sum += score, square += score * score;
    }
    const double mean = sum / n;
    return {mean, std::sqrt((square / n - mean * mean) / (n - 1))};
}

TEST(EmissionTexture, FloorUnderAHalfBlackLightAgreesWithQuadratureByEveryStrategy) {
    const FloorUnderTexturedLight f;
    const double expected = f.expected(true), untextured = f.expected(false);
    // Over the white half the floor gets more than half the untextured light, and less than all.
    ASSERT_GT(expected, 0.55 * untextured);
    ASSERT_LT(expected, 0.95 * untextured);
    const int spp = 1 << 14;
    std::vector<std::pair<const char*, Estimate>> estimates;
    for (const LightSampling lights : {LightSampling::nee, LightSampling::mis}) {
        SceneDescription d = f.scene(spp, true);
        d.settings.estimator.light_sampling = lights;
        estimates.push_back({name_of(lights), rendered(d)});
    }
    const Scene scene = build_scene(f.scene(spp, true));
    estimates.push_back({"bsdf", bsdf_sampling_alone(scene, glm::vec3(float(f.px), 0.0f, 0.0f), 1 << 17, 7)});
    for (const auto& [name, e] : estimates) {
        std::printf("%s: %.6f +- %.6f (quadrature %.6f, untextured %.6f)\n", name, e.mean, e.standard_error, expected,
                    untextured);
        // Five standard errors (the estimate's own spread), and that bound far below the gap
        // to the untextured light, so the test tells the two apart.
        EXPECT_NEAR(e.mean, expected, 5.0 * e.standard_error + 1e-4 * expected)
            << name << ": reproduce with FloorUnderTexturedLight::scene(" << spp << ", true), seed 0";
        EXPECT_GT(std::fabs(e.mean - untextured), 10.0 * e.standard_error) << name;
        EXPECT_LT(5.0 * e.standard_error, 0.05 * expected) << name;
    }
    // The same strategies see the untextured light's own value.
    SceneDescription plain = f.scene(spp, false);
    plain.settings.estimator.light_sampling = LightSampling::mis;
    const Estimate e = rendered(plain);
    EXPECT_NEAR(e.mean, untextured, 5.0 * e.standard_error + 1e-4 * untextured);
    EXPECT_GT(std::fabs(e.mean - expected), 10.0 * e.standard_error);
}

TEST(EmissionTexture, ATextureOnTheSecondSetIsReadThereByLightSamplesAndHits) {
    // The same light with its texture on TEXCOORD_1, mirrored: the floor point now lies under
    // the light's dark half. Light samples (NEE) and BSDF-found hits (MIS) must both read set 1:
    // each agrees with the mirrored quadrature, far from the set-0 value.
    const FloorUnderTexturedLight f;
    const double mirrored = f.expected(true, true), first_set = f.expected(true, false);
    ASSERT_LT(mirrored, 0.8 * first_set);
    for (const LightSampling lights : {LightSampling::nee, LightSampling::mis}) {
        SceneDescription d = f.scene(1 << 14, true, true);
        d.settings.estimator.light_sampling = lights;
        const Estimate e = rendered(d);
        std::printf("%s: %.6f +- %.6f (set 1 quadrature %.6f, set 0 %.6f)\n", name_of(lights), e.mean, e.standard_error, mirrored,
                    first_set);
        EXPECT_NEAR(e.mean, mirrored, 5.0 * e.standard_error + 1e-4 * mirrored)
            << name_of(lights) << ": reproduce with FloorUnderTexturedLight::scene(16384, true, true)";
        EXPECT_GT(std::fabs(e.mean - first_set), 10.0 * e.standard_error) << name_of(lights);
    }
}

TEST(EmissionTexture, ImageIsTheSameBitsForAnySchedule) {
    // A wide view of the floor under the textured light, MIS: both the light samples' and the
    // hits' lookups, on every thread count, integrator, batch, ISA and accelerator.
    SceneDescription d = FloorUnderTexturedLight().scene(8, true);
    d.camera.eye = glm::vec3(0.0f, -1.5f, 0.6f);
    d.camera.look_at = glm::vec3(0.0f, 0.0f, 0.3f);
    d.camera.fov_degrees = 70.0f;
    d.settings.width = d.settings.height = 16;
    d.settings.max_bounces = 4;
    d.settings.estimator.light_sampling = LightSampling::mis;
    const test::RenderedFilm r = test::render_film(d, Integrator::wavefront);
    EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
    test::expect_same_film_for_any_schedule(d, r.film);
    // And the texture is seen: without it the image differs.
    SceneDescription plain = d;
    plain.materials[1].emission_texture = -1;
    EXPECT_FALSE(r.film == test::render_film(plain, Integrator::wavefront).film);
}

TEST(EmissionTexture, MemoryEstimateAndSceneHashCountIt) {
    const FloorUnderTexturedLight f;
    const SceneDescription d = f.scene(4, true), plain = f.scene(4, false);
    const Scene scene = build_scene(d), untextured = build_scene(plain);
    EXPECT_GT(scene.lights.bytes(), untextured.lights.bytes());
    EXPECT_GT(estimate_render_memory(scene, RenderOptions{}).lights, estimate_render_memory(untextured, RenderOptions{}).lights);
    // A checkpoint of another emission texture is refused: the hash sees its texels, and which
    // texture the light reads.
    SceneDescription flipped = d;
    flipped.textures[0] = texture_of(2, 1, [](int x, int) { return glm::vec4(float(1 - x), float(1 - x), float(1 - x), 1.0f); },
                                     TextureWrap::clamp);
    EXPECT_NE(scene_content_hash(d), scene_content_hash(flipped));
    SceneDescription unread = d;
    unread.materials[1].emission_texture = -1;
    EXPECT_NE(scene_content_hash(d), scene_content_hash(unread));
}

// Four lights side by side, each a quad of side 0.5 at height 1 facing down, all emitting 4 but
// their textures: uniform 0.1, black-then-white, uniform 1, none.
SceneDescription four_textured_lights(int spp, LightSelection selection) {
    SceneDescription d = FloorUnderTexturedLight().scene(spp, true);
    d.meshes.pop_back();
    d.textures.push_back(texture_of(2, 2, [](int, int) { return glm::vec4(0.1f); }));
    d.textures.push_back(texture_of(2, 2, [](int, int) { return glm::vec4(1.0f); }));
    for (int k = 0; k < 4; ++k) {
        Material m = d.materials[1];
        m.name = "light" + std::to_string(k);
        m.emission_texture = k < 3 ? std::array<int32_t, 3>{1, 0, 2}[std::size_t(k)] : -1;
        d.materials.push_back(m);
        TriangleMesh lamp = downward_light(0.25f, 1.0f);
        for (glm::vec3& v : lamp.vertices) v.x += -0.9f + 0.6f * float(k);
        lamp.material = uint32_t(d.materials.size() - 1);
        d.meshes.push_back(lamp);
    }
    d.settings.estimator.light_selection = selection;
    return d;
}

TEST(EmissionTexture, SelectionByPowerAndTreeWeighsTheTexturesMeanAndStaysUnbiased) {
    const Estimate by_area = rendered(four_textured_lights(1 << 14, LightSelection::area));
    for (const LightSelection how : {LightSelection::power, LightSelection::bvh}) {
        SCOPED_TRACE(name_of(how));
        const SceneDescription d = four_textured_lights(1 << 14, how);
        const Scene scene = build_scene(d);
        ASSERT_EQ(scene.lights.size(), 8u);
        ASSERT_FALSE(scene.emitter_selection.empty());
        // The dim texture's emitter (mean 0.1) is picked less often than the white one's (mean 1),
        // which is picked as often as the untextured one (the same power; the distribution's
        // differences of its cdf round apart): the texture's mean counts.
        const glm::vec3 from(float(FloorUnderTexturedLight::px), 0.0f, 0.0f), normal(0.0f, 0.0f, 1.0f);
        if (how == LightSelection::power) {
            EXPECT_LT(scene.emitter_selection.probability(from, normal, 0), 0.2f * scene.emitter_selection.probability(from, normal, 4));
            EXPECT_FLOAT_EQ(scene.emitter_selection.probability(from, normal, 4), scene.emitter_selection.probability(from, normal, 6));
        }
        // Every pick's pdf is the pdf the hit on its triangle asks for, bit for bit.
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
        for (int k = 0; k < 2000; ++k) {
            LightSample s;
            float u_choice = uniform(rng);
            if (!scene.emitter_selection.sample(scene.lights, from, normal, u_choice, uniform(rng), uniform(rng), s)) continue;
            // Which triangle: the one whose plane point is s.position (they do not overlap).
            bool found = false;
            for (std::size_t e = 0; e < scene.lights.size(); ++e) {
                const uint32_t i = scene.lights.triangle_of(e);
                const glm::vec3 a = scene.triangles.vertex0(i), e1 = scene.triangles.edge1(i), e2 = scene.triangles.edge2(i);
                const glm::vec2 r(s.position.x - a.x, s.position.y - a.y);
                const float det = e1.x * e2.y - e1.y * e2.x;
                const float u = (r.x * e2.y - r.y * e2.x) / det, v = (e1.x * r.y - e1.y * r.x) / det;
                if (u < -1e-5f || v < -1e-5f || u + v > 1.0f + 1e-5f) continue;
                EXPECT_EQ(s.pdf_area, scene.emitter_selection.pdf_area(from, normal, i)) << "emitter " << e;
                found = true;
                break;
            }
            EXPECT_TRUE(found);
        }
        const Estimate e = rendered(d);
        std::printf("%s: %.6f +- %.6f, area: %.6f +- %.6f\n", name_of(how), e.mean, e.standard_error, by_area.mean,
                    by_area.standard_error);
        const double se = std::hypot(e.standard_error, by_area.standard_error);
        EXPECT_NEAR(e.mean, by_area.mean, 5.0 * se) << "reproduce with four_textured_lights(16384, " << name_of(how) << ")";
        EXPECT_LT(5.0 * se, 0.05 * by_area.mean);
    }
}

// The mirror caustic's scene with a larger light whose upward face (the one the mirror shows the
// floor) is textured black-then-white: the floor is lit through the mirror alone, so the camera
// paths' estimate and light tracing's (and photons', which trace the same light paths) must
// agree, and differ from the untextured light's.
SceneDescription textured_mirror_caustic(int spp, uint64_t seed, CausticPaths caustics, bool textured) {
    SceneDescription d = test::MirrorCaustic().scene(spp, seed, caustics);
    const float h = 0.4f;
    TriangleMesh& lamp = d.meshes[2];
    lamp.vertices = {{-h, -h, 1}, {h, -h, 1}, {h, h, 1}, {-h, h, 1}};
    lamp.uvs = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    lamp.parallelogram = false;
    if (textured) {
        d.materials[2].emission_texture = 0;
        d.textures = {black_then_white()};
    }
    d.settings.width = d.settings.height = 12;
    return d;
}

// The image's mean (the floor's radiance averaged over the view) per seed: mean and standard error.
Estimate image_mean_over_seeds(CausticPaths caustics, bool textured, int spp, int seeds) {
    std::vector<double> means;
    for (int s = 0; s < seeds; ++s) {
        const SceneDescription d = textured_mirror_caustic(spp, uint64_t(100 + s), caustics, textured);
        const test::RenderedFilm r = test::render_film(d, Integrator::wavefront);
        EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
        double sum = 0.0;
        for (uint32_t p = 0; p < uint32_t(d.settings.width * d.settings.height); ++p) sum += r.film.pixel_mean(p).y;
        means.push_back(sum / (d.settings.width * d.settings.height));
    }
    double mean = 0.0, var = 0.0;
    for (double m : means) mean += m / seeds;
    for (double m : means) var += (m - mean) * (m - mean) / (seeds - 1);
    return {mean, std::sqrt(var / seeds)};
}

TEST(EmissionTexture, LightTracingAndPhotonsCarryTheTextureFromWherePathsStart) {
    const int seeds = 8;
    const Estimate path = image_mean_over_seeds(CausticPaths::path, true, 64, seeds);
    const Estimate untextured = image_mean_over_seeds(CausticPaths::light_tracing, false, 16, seeds);
    // Two-sided Student t for 1e-4 with 14 degrees of freedom (Welch's, about): 5.4.
    const double t = 5.4;
    for (const CausticPaths caustics : {CausticPaths::light_tracing, CausticPaths::photons}) {
        const Estimate e = image_mean_over_seeds(caustics, true, 16, seeds);
        std::printf("%s: %.6f +- %.6f, path: %.6f +- %.6f, untextured: %.6f +- %.6f\n", name_of(caustics), e.mean,
                    e.standard_error, path.mean, path.standard_error, untextured.mean, untextured.standard_error);
        const double se = std::hypot(e.standard_error, path.standard_error);
        EXPECT_NEAR(e.mean, path.mean, t * se) << name_of(caustics) << ": seeds 100 to " << 100 + seeds - 1;
        const double se_untextured = std::hypot(e.standard_error, untextured.standard_error);
        EXPECT_GT(std::fabs(e.mean - untextured.mean), 2.0 * t * se_untextured) << name_of(caustics);
    }
}

}  // namespace
}  // namespace wt
