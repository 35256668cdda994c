// Renders with light selection by power and by the light tree: the same image in expectation as
// selection by area (a per-pixel z-test, nee and mis, a rough metal in view), the white furnace
// of a room whose every wall is many emitters, and the same bits for any schedule. Compiled
// twice: light_selection_test (a few seconds) and light_selection_long_test (WT_LONG_TESTS=1,
// label `long`: more emitters, pixels and samples).

#include <gtest/gtest.h>

#include "core/scene/scene.h"
#include "core/scene_file/scene_loader.h"
#include "many_lights_scene.h"
#include "render_helpers.h"
#include "white_furnace_check.h"

#ifndef WT_LONG_TESTS
#define WT_LONG_TESTS 0
#endif

namespace wt {
namespace {

constexpr int kGrid = WT_LONG_TESTS ? 40 : 16;  // emitters per side of the ceiling's grid
constexpr int kSpp = WT_LONG_TESTS ? 4096 : 512;
constexpr int kSide = WT_LONG_TESTS ? 32 : 16;

std::string pixel_name(uint32_t p) { return "pixel " + std::to_string(p); }

SceneDescription room(LightSampling ls, LightSelection how) {
    SceneDescription d = test::many_lights_room(kGrid, ls, how);
    d.settings.spp = kSpp;
    d.settings.width = d.settings.height = kSide;
    return d;
}

TEST(ManyLights, PowerAndTreeAgreeWithAreaPerPixel) {
    for (LightSampling ls : {LightSampling::nee, LightSampling::mis}) {
        SCOPED_TRACE(name_of(ls));
        const Film area = test::render_film(room(ls, LightSelection::area), Integrator::wavefront).film;
        for (LightSelection how : {LightSelection::power, LightSelection::bvh}) {
            SCOPED_TRACE(name_of(how));
            SceneDescription d = room(ls, how);
            d.settings.seed = 7;  // independent of the area render's samples
            const test::RenderedFilm r = test::render_film(d, Integrator::wavefront);
            EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
            test::expect_films_agree(area, r.film, pixel_name);
        }
    }
}

// With a "lights" list beside the emitters, the tree picks among the emitters within the area
// lights' share: still the same image.
TEST(ManyLights, TreeBesideAListedPointLightAgreesWithArea) {
    SceneDescription d = room(LightSampling::mis, LightSelection::area);
    LightDescription point;
    point.type = LightType::point;
    point.position = {-1.0f, 1.0f, 1.5f};
    point.intensity = glm::vec3(3.0f);
    d.lights = {point};
    const Film area = test::render_film(d, Integrator::wavefront).film;
    d.settings.estimator.light_selection = LightSelection::bvh;
    d.settings.seed = 9;
    test::expect_films_agree(area, test::render_film(d, Integrator::wavefront).film, pixel_name);
}

// A closed cube whose six faces are k x k quads of emitters (Le = 1, albedo rho): every pixel
// converges to Le / (1 - rho), whichever emitter the tree sends each light sample to.
SceneDescription emitter_furnace(int k, float rho, LightSelection how, LightSampling ls) {
    SceneDescription d;
    Material m;
    m.name = "furnace";
    m.albedo = glm::vec3(rho);
    m.emission = glm::vec3(1.0f);
    d.materials.push_back(m);
    const glm::vec3 corner[6] = {{-1, -1, -1}, {-1, -1, 1}, {-1, -1, -1}, {-1, 1, -1}, {-1, -1, -1}, {1, -1, -1}};
    const glm::vec3 u_axis[6] = {{0, 2, 0}, {2, 0, 0}, {2, 0, 0}, {0, 0, 2}, {0, 0, 2}, {0, 2, 0}};
    const glm::vec3 v_axis[6] = {{2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
    TriangleMesh mesh;
    for (int f = 0; f < 6; ++f)
        for (int j = 0; j < k; ++j)
            for (int i = 0; i < k; ++i) {
                const uint32_t base = uint32_t(mesh.vertices.size());
                const glm::vec3 o = corner[f] + (float(i) / float(k)) * u_axis[f] + (float(j) / float(k)) * v_axis[f];
                const glm::vec3 du = u_axis[f] / float(k), dv = v_axis[f] / float(k);
                mesh.vertices.insert(mesh.vertices.end(), {o, o + du, o + du + dv, o + dv});
                mesh.triangles.push_back({base, base + 2, base + 1});  // facing into the cube
                mesh.triangles.push_back({base, base + 3, base + 2});
            }
    d.meshes.push_back(mesh);
    d.camera.eye = glm::vec3(0.0f);
    d.camera.look_at = glm::vec3(1.0f, 0.0f, 0.0f);
    d.camera.up = glm::vec3(0, 0, 1);
    d.camera.fov_degrees = 40.0f;
    d.settings.width = d.settings.height = 12;
    d.settings.spp = 128;
    d.settings.shadow_rays = 2;
    d.settings.estimator.light_selection = how;
    d.settings.estimator.light_sampling = ls;
    return d;
}

TEST(ManyLights, WhiteFurnaceOfEmittersStaysAtLeOverOneMinusRho) {
    for (LightSampling ls : {LightSampling::nee, LightSampling::mis})
        for (LightSelection how : {LightSelection::power, LightSelection::bvh}) {
            SCOPED_TRACE(testing::Message() << name_of(ls) << " " << name_of(how));
            const SceneDescription d = emitter_furnace(6, 0.5f, how, ls);
            // Each face's normal into the cube: otherwise the room would be dark.
            const Scene scene = build_scene(d);
            ASSERT_EQ(scene.lights.size(), 6u * 6u * 6u * 2u);
            ASSERT_FALSE(scene.emitter_selection.empty());
            test::expect_white_furnace(test::render_film(d, Integrator::wavefront), d, 1.0 / (1.0 - 0.5));
        }
}

TEST(ManyLights, SameBitsForAnySchedule) {
    for (LightSampling ls : {LightSampling::nee, LightSampling::mis})
        for (LightSelection how : {LightSelection::power, LightSelection::bvh}) {
            SCOPED_TRACE(testing::Message() << name_of(ls) << " " << name_of(how));
            SceneDescription d = test::many_lights_room(10, ls, how);
            d.settings.spp = 4;
            const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 1);
            EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
            test::expect_same_film_for_any_schedule(d, r.film);
        }
}

// The repository's scenes, each with few lights, render the same bits with the default as with
// selection by area, and build no selection.
TEST(ManyLights, TodaysScenesKeepTheirBitsWithTheDefault) {
    for (const char* name : {"hexroom.json", "furnace.json", "caustic_mirror.json", "envroom.json"}) {
        SCOPED_TRACE(name);
        SceneDescription d = load_scene_file(std::string(WT_SCENES_DIR) + "/" + name);
        ASSERT_EQ(d.settings.estimator.light_selection, LightSelection::automatic);
        d.settings.width = d.settings.height = 12;
        d.settings.spp = 2;
        EXPECT_TRUE(build_scene(d).emitter_selection.empty());
        const Film automatic = test::render_film(d, Integrator::wavefront).film;
        d.settings.estimator.light_selection = LightSelection::area;
        EXPECT_TRUE(automatic == test::render_film(d, Integrator::wavefront).film);
    }
}

// With one emitter every selection is the area's: same scene, same bits.
TEST(ManyLights, OneEmitterKeepsTheAreaBits) {
    SceneDescription d = test::many_lights_room(1, LightSampling::mis, LightSelection::area);
    d.settings.spp = 4;
    const Film area = test::render_film(d, Integrator::wavefront).film;
    for (LightSelection how : {LightSelection::power, LightSelection::bvh}) {
        d.settings.estimator.light_selection = how;
        EXPECT_TRUE(area == test::render_film(d, Integrator::wavefront).film) << name_of(how);
    }
}

}  // namespace
}  // namespace wt
