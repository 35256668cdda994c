// The rough materials in the renderer: a rough sphere filling the view inside a cube whose walls
// emit 1 and reflect nothing, so each pixel is the sphere's directional albedo (never above 1;
// near 1 for a smooth-ish white metal, the known single-scattering loss at roughness 1); light
// samples alone (nee) and with the BSDF samples (mis) agree; the same bits from every schedule
// and integrator, with light tracing and photons on; roughness 0 is the mirror and the glass bit
// for bit; and the scene file's keys and refusals.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/scene_file/scene_loader.h"
#include "material_scene_file.h"
#include "render_helpers.h"
#include "statistics.h"
#include "test_scenes.h"

namespace wt {
namespace {

using test::expect_refused;
using test::scene_with_sphere_material;

Material rough(MaterialType type, float roughness, float ior = 1.5f) {
    Material m;
    m.name = "rough";
    m.type = type;
    m.roughness = roughness;
    m.ior = ior;
    return m;
}

// The furnace cube's walls emit 1 and reflect nothing; a sphere of material m fills the view.
SceneDescription sphere_in_furnace(const Material& m, LightSampling sampling, int spp = 64) {
    SceneDescription d = test::furnace_cube(0.0f, 1.0f);
    d.materials.push_back(m);
    d.spheres.push_back({glm::vec3(0.6f, 0.0f, 0.0f), 0.3f, 1});
    d.settings.spp = spp;
    d.settings.estimator.light_sampling = sampling;
    return d;
}

struct ImageStats {
    double mean = 0.0;
    int brighter_than_walls = 0;  // pixels above 1 by more than 4 standard errors
};

ImageStats image_stats(const Film& film) {
    ImageStats s;
    const int pixels = film.width() * film.height();
    for (int p = 0; p < pixels; ++p) {
        const double mean = film.pixel_mean(uint32_t(p)).x;
        const double se = std::sqrt(film.pixel_sample_variance(uint32_t(p)).x / film.pixel_count(uint32_t(p)));
        if (mean > 1.0 + 4.0 * se + 1e-6) ++s.brighter_than_walls;
        s.mean += mean / pixels;
    }
    return s;
}

TEST(MicrofacetRender, RoughSpheresReflectNoMoreThanTheFurnaceGivesAndNeeAgreesWithMis) {
    struct Case {
        Material m;
        double low, high;  // the image mean's bounds
    };
    Material white_metal = rough(MaterialType::rough_conductor, 0.2f);
    Material rough_metal = rough(MaterialType::rough_conductor, 1.0f);
    Material copper = rough(MaterialType::rough_conductor, 0.5f);
    copper.f0 = glm::vec3(0.95f, 0.64f, 0.54f);
    for (const Case& c : {Case{white_metal, 0.95, 1.0}, Case{rough_metal, 0.25, 0.6}, Case{copper, 0.8, 1.0},
                          Case{rough(MaterialType::rough_glass, 0.4f), 0.8, 1.0}}) {
        const Film nee = test::render_film(sphere_in_furnace(c.m, LightSampling::nee), Integrator::wavefront).film;
        const Film mis = test::render_film(sphere_in_furnace(c.m, LightSampling::mis), Integrator::wavefront).film;
        for (const Film* f : {&nee, &mis}) {
            const ImageStats s = image_stats(*f);
            EXPECT_EQ(s.brighter_than_walls, 0) << int(c.m.type) << " " << c.m.roughness;
            EXPECT_GT(s.mean, c.low) << int(c.m.type) << " " << c.m.roughness;
            EXPECT_LT(s.mean, c.high) << int(c.m.type) << " " << c.m.roughness;
        }
        test::expect_films_agree(nee, mis, [](uint32_t) { return std::string("microfacet furnace"); });
    }
}

// With Kulla & Conty's compensation a white rough metal shows the walls' 1 at every pixel (a
// convex sphere sees only the walls), with nee and mis alike, where single scattering shows the
// known loss; a coloured metal gains light but no channel passes 1.
TEST(MicrofacetRender, MultipleScatteringMakesAWhiteRoughMetalReflectEverything) {
    Material white = rough(MaterialType::rough_conductor, 1.0f);
    Material copper = rough(MaterialType::rough_conductor, 0.6f);
    copper.f0 = glm::vec3(0.95f, 0.64f, 0.54f);
    for (LightSampling sampling : {LightSampling::nee, LightSampling::mis}) {
        SceneDescription on = sphere_in_furnace(white, sampling);
        on.settings.accuracy.multiple_scattering = MultipleScattering::kulla_conty;
        const ImageStats compensated = image_stats(test::render_film(on, Integrator::wavefront).film);
        EXPECT_EQ(compensated.brighter_than_walls, 0);
        // The albedo table's error (multiple_scattering_test) plus a little for the noise.
        EXPECT_NEAR(compensated.mean, 1.0, 0.006);
        const ImageStats single = image_stats(test::render_film(sphere_in_furnace(white, sampling), Integrator::wavefront).film);
        EXPECT_LT(single.mean, 0.6);
        SceneDescription copper_on = sphere_in_furnace(copper, sampling);
        copper_on.settings.accuracy.multiple_scattering = MultipleScattering::kulla_conty;
        const ImageStats copper_compensated = image_stats(test::render_film(copper_on, Integrator::wavefront).film);
        const ImageStats copper_single = image_stats(test::render_film(sphere_in_furnace(copper, sampling), Integrator::wavefront).film);
        EXPECT_EQ(copper_compensated.brighter_than_walls, 0);
        EXPECT_GT(copper_compensated.mean, copper_single.mean + 0.02);
    }
}

// A white metal is bright, a black one (F0 = 0) is black: the lobe is what lights the image.
TEST(MicrofacetRender, BlackMetalIsBlack) {
    Material black = rough(MaterialType::rough_conductor, 0.4f);
    black.f0 = glm::vec3(0.0f);
    const ImageStats s = image_stats(test::render_film(sphere_in_furnace(black, LightSampling::mis, 16), Integrator::wavefront).film);
    // Schlick's F0 = 0 still reflects at grazing microfacets: a little, never much.
    EXPECT_LT(s.mean, 0.2);
    EXPECT_GT(s.mean, 0.0);
}

// A lit room with every kind of surface: a rough metal, a rough glass, a smooth conductor (so
// light tracing runs) and diffuse walls; the same bits from either integrator and any schedule.
SceneDescription room_with_rough_spheres(CausticPaths caustics, LightSampling sampling) {
    SceneDescription d = test::hexroom(24, 16, 4);
    const uint32_t first = uint32_t(d.materials.size());
    d.materials.push_back(rough(MaterialType::rough_conductor, 0.3f));
    d.materials.push_back(rough(MaterialType::rough_glass, 0.3f));
    Material smooth = rough(MaterialType::conductor, 0.0f);
    smooth.f0 = glm::vec3(0.9f, 0.7f, 0.3f);
    d.materials.push_back(smooth);
    for (std::size_t i = 0; i < d.spheres.size(); ++i) d.spheres[i].material = first + uint32_t(i % 3);
    d.settings.estimator.caustics = caustics;
    d.settings.estimator.light_sampling = sampling;
    return d;
}

TEST(MicrofacetRender, SameBitsFromEveryScheduleWithLightTracingAndPhotons) {
    for (CausticPaths caustics : {CausticPaths::path, CausticPaths::light_tracing, CausticPaths::photons})
        for (LightSampling sampling : {LightSampling::nee, LightSampling::mis}) {
            const SceneDescription d = room_with_rough_spheres(caustics, sampling);
            ASSERT_GE(d.spheres.size(), 2u);
            const Scene scene = build_scene(d);
            EXPECT_EQ(scene.light_traces_caustics, caustics != CausticPaths::path);
            const Film film = test::render_film(d, Integrator::wavefront).film;
            test::expect_same_film_for_any_schedule(d, film);
        }
}

// Only the GGX reflection lobes change: a scene without them renders the same bits with
// compensation as without, a room with them does not, and renders it with the same bits from
// every schedule and both integrators, light tracing and photons included.
TEST(MicrofacetRender, MultipleScatteringChangesOnlyRoughLobesAndKeepsBitIdentity) {
    SceneDescription plain = test::hexroom(24, 16, 4);
    SceneDescription plain_on = plain;
    plain_on.settings.accuracy.multiple_scattering = MultipleScattering::kulla_conty;
    EXPECT_TRUE(test::render_film(plain, Integrator::wavefront).film == test::render_film(plain_on, Integrator::wavefront).film);
    for (CausticPaths caustics : {CausticPaths::path, CausticPaths::photons}) {
        const SceneDescription rough_room = room_with_rough_spheres(caustics, LightSampling::mis);
        SceneDescription on = rough_room;
        on.settings.accuracy.multiple_scattering = MultipleScattering::kulla_conty;
        const Film film = test::render_film(on, Integrator::wavefront).film;
        EXPECT_FALSE(film == test::render_film(rough_room, Integrator::wavefront).film);
        test::expect_same_film_for_any_schedule(on, film);
    }
}

// Roughness 0 from the scene file is today's mirror and glass: the same image bits.
TEST(MicrofacetRender, RoughnessZeroIsTheMirrorAndTheGlassBitForBit) {
    const auto render = [](const std::string& material) {
        return test::render_film(parse_scene_json(scene_with_sphere_material(material), "test.json"), Integrator::wavefront).film;
    };
    const Film mirror = render(R"({"type": "mirror"})");
    EXPECT_TRUE(mirror == render(R"({"type": "conductor", "f0": [1, 1, 1], "roughness": 0})"));
    EXPECT_TRUE(mirror == render(R"({"type": "conductor"})"));
    EXPECT_FALSE(mirror == render(R"({"type": "conductor", "roughness": 0.2})"));
    const Film glass = render(R"({"type": "glass", "ior": 1.5})");
    EXPECT_TRUE(glass == render(R"({"type": "rough_glass", "ior": 1.5, "roughness": 0})"));
    EXPECT_FALSE(glass == render(R"({"type": "rough_glass", "ior": 1.5, "roughness": 0.2})"));
    // Index-matched: the smooth glass, straight through, whatever the roughness.
    EXPECT_TRUE(render(R"({"type": "glass", "ior": 1})") == render(R"({"type": "rough_glass", "ior": 1, "roughness": 0.7})"));
}

TEST(MicrofacetSceneFile, ReadsTheKeys) {
    const SceneDescription d = parse_scene_json(
        scene_with_sphere_material(R"({"type": "conductor", "eta": [0.2, 0.9, 1.1], "k": [3.9, 2.4, 2.2], "roughness": 0.5})"),
        "test.json");
    const Material& m = d.materials[2];
    EXPECT_EQ(m.type, MaterialType::rough_conductor);
    EXPECT_FLOAT_EQ(m.roughness, 0.5f);
    EXPECT_FLOAT_EQ(m.eta.y, 0.9f);
    EXPECT_FLOAT_EQ(m.k.x, 3.9f);
    const SceneDescription g =
        parse_scene_json(scene_with_sphere_material(R"({"type": "rough_glass", "ior": 1.33, "roughness": 1})"), "test.json");
    EXPECT_EQ(g.materials[2].type, MaterialType::rough_glass);
    EXPECT_FLOAT_EQ(g.materials[2].ior, 1.33f);
}


TEST(MicrofacetSceneFile, ReadsMultipleScatteringAndRefusesAnUnknownName) {
    std::string text = scene_with_sphere_material(R"({"type": "conductor", "roughness": 0.5})");
    EXPECT_EQ(parse_scene_json(text, "test.json").settings.accuracy.multiple_scattering, MultipleScattering::none);
    const std::string render_key = "\"render\": {";
    const std::size_t at = text.find(render_key);
    ASSERT_NE(at, std::string::npos);
    std::string on = text, bad = text;
    on.insert(at + render_key.size(), R"("multiple_scattering": "kulla_conty", )");
    bad.insert(at + render_key.size(), R"("multiple_scattering": "yes", )");
    const SceneDescription d = parse_scene_json(on, "test.json");
    EXPECT_EQ(d.settings.accuracy.multiple_scattering, MultipleScattering::kulla_conty);
    // The loaders leave the materials alone; the scene builder marks the GGX reflection lobes.
    EXPECT_FALSE(d.materials[2].multiple_scattering);
    const Scene scene = build_scene(d);
    EXPECT_TRUE(scene.materials[2].multiple_scattering);
    for (std::size_t i = 0; i < 2; ++i) EXPECT_FALSE(scene.materials[i].multiple_scattering) << i;
    try {
        parse_scene_json(bad, "test.json");
        ADD_FAILURE() << "accepted multiple_scattering \"yes\"";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("render.multiple_scattering: must be one of \"none\", \"kulla_conty\""), std::string::npos)
            << e.what();
    }
}

TEST(MicrofacetSceneFile, RefusesBadValuesNamingTheField) {
    expect_refused(R"({"type": "conductor", "roughness": 1.5})", "materials.ball.roughness: must be in [0, 1], got 1.5");
    expect_refused(R"({"type": "conductor", "roughness": -0.1})", "materials.ball.roughness: must be in [0, 1]");
    expect_refused(R"({"type": "conductor", "f0": [1.2, 0, 0]})", "materials.ball.f0[0]: must be in [0, 1]");
    expect_refused(R"({"type": "conductor", "f0": [1, 1, 1], "eta": [1, 1, 1], "k": [1, 1, 1]})", "materials.ball.eta: give either f0");
    expect_refused(R"({"type": "conductor", "eta": [1, 1, 1]})", "materials.ball.k: required key is missing");
    expect_refused(R"({"type": "conductor", "eta": [0, 1, 1], "k": [1, 1, 1]})", "materials.ball.eta[0]: must be positive");
    expect_refused(R"({"type": "conductor", "k": [-1, 1, 1], "eta": [1, 1, 1]})", "materials.ball.k[0]: must be non-negative");
    expect_refused(R"({"type": "conductor", "ior": 1.5})", "ior");
    expect_refused(R"({"type": "rough_glass", "roughness": 0.5})", "materials.ball.ior");
    expect_refused(R"({"type": "rough_glass", "ior": 0, "roughness": 0.5})", "materials.ball.ior: must be positive");
    expect_refused(R"({"type": "rough_glass", "ior": 1.5, "roughness": 0.5, "f0": [1, 1, 1]})", "f0");
    expect_refused(R"({"type": "conductor", "emission": [1, 1, 1]})", "materials.ball.emission: emission is not supported");
}

}  // namespace
}  // namespace wt
