// glTF's metallic-roughness material in the renderer: in the emitting furnace, light samples
// alone (nee) and with BSDF samples (mis) agree (the light samples at a principled vertex are
// weighted against its lobe mixture's pdf); a lit room with principled spheres (a plastic, a
// half metal, a smooth plastic, and the light itself) renders the same bits from both integrators and every schedule,
// with light tracing and photons on; metallic 1 roughness 0 is the mirror bit for bit; and the
// scene file's keys and refusals, each naming its field.

#include <string>

#include <gtest/gtest.h>

#include "bsdf_helpers.h"
#include "core/scene_file/scene_loader.h"
#include "material_scene_file.h"
#include "render_helpers.h"
#include "test_scenes.h"

namespace wt {
namespace {

using test::expect_refused;
using test::principled;
using test::scene_with_sphere_material;


TEST(PrincipledRender, NeeAgreesWithMisInTheFurnace) {
    for (const Material& m : {principled(glm::vec3(0.8f), 0.0f, 0.4f), principled({0.9f, 0.6f, 0.3f}, 0.5f, 0.15f)}) {
        const auto render = [&](LightSampling sampling) {
            SceneDescription d = test::furnace_cube(0.0f, 1.0f);
            d.materials.push_back(m);
            d.spheres.push_back({glm::vec3(0.6f, 0.0f, 0.0f), 0.3f, 1});
            d.settings.spp = 64;
            d.settings.estimator.light_sampling = sampling;
            return test::render_film(d, Integrator::wavefront).film;
        };
        const Film nee = render(LightSampling::nee), mis = render(LightSampling::mis);
        test::expect_films_agree(nee, mis, [](uint32_t) { return std::string("principled furnace"); });
        // The sphere is lit: its centre pixel reflects most of the walls' 1 (within 40 degrees
        // of its normal the material reflects at most 1, and these base colours at least 0.7).
        const uint32_t centre = uint32_t(nee.height() / 2 * nee.width() + nee.width() / 2);
        EXPECT_GT(nee.pixel_mean(centre).x, 0.7);
        EXPECT_LT(nee.pixel_mean(centre).x, 1.05);
    }
}

SceneDescription room_with_principled_spheres(CausticPaths caustics, LightSampling sampling) {
    SceneDescription d = test::hexroom(24, 16, 4);
    const uint32_t first = uint32_t(d.materials.size());
    d.materials.push_back(principled({0.2f, 0.4f, 0.8f}, 0.0f, 0.3f));
    d.materials.push_back(principled({0.95f, 0.64f, 0.54f}, 0.5f, 0.5f));
    d.materials.push_back(principled({0.9f, 0.9f, 0.9f}, 0.0f, 0.0f));
    // The light itself principled: an emitting glTF material, sampled as a light.
    for (Material& m : d.materials)
        if (m.is_emissive()) m = principled(glm::vec3(0.3f), 0.2f, 0.5f, 1.5f, m.emission);
    Material mirror;  // so light tracing runs
    mirror.type = MaterialType::mirror;
    d.materials.push_back(mirror);
    for (std::size_t i = 0; i < d.spheres.size(); ++i) d.spheres[i].material = first + uint32_t(i % 4);
    d.settings.estimator.caustics = caustics;
    d.settings.estimator.light_sampling = sampling;
    return d;
}

TEST(PrincipledRender, SameBitsFromBothIntegratorsAndEverySchedule) {
    for (CausticPaths caustics : {CausticPaths::path, CausticPaths::light_tracing, CausticPaths::photons})
        for (LightSampling sampling : {LightSampling::nee, LightSampling::mis}) {
            const SceneDescription d = room_with_principled_spheres(caustics, sampling);
            ASSERT_GE(d.spheres.size(), 4u);
            const Film film = test::render_film(d, Integrator::wavefront).film;
            test::expect_same_film_for_any_schedule(d, film);
            // And the principled spheres changed the image: the same room with them diffuse differs.
            SceneDescription diffuse = d;
            for (Material& m : diffuse.materials)
                if (m.type == MaterialType::principled) m.type = MaterialType::lambertian, m.albedo = m.base_color;
            EXPECT_FALSE(film == test::render_film(diffuse, Integrator::wavefront).film);
        }
}


TEST(PrincipledSceneFile, ReadsTheKeysAndMetallicOneSmoothIsTheMirror) {
    const SceneDescription d = parse_scene_json(
        scene_with_sphere_material(
            R"({"type": "principled", "base_color": [0.9, 0.5, 0.1], "metallic": 0.3, "roughness": 0.6, "ior": 1.33})"),
        "test.json");
    const Material& m = d.materials[2];
    EXPECT_EQ(m.type, MaterialType::principled);
    EXPECT_EQ(m.base_color, glm::vec3(0.9f, 0.5f, 0.1f));
    EXPECT_FLOAT_EQ(m.metallic, 0.3f);
    EXPECT_FLOAT_EQ(m.roughness, 0.6f);
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    // Emission, on a mesh (as every emitter), as glTF's emissive metallic-roughness materials have it.
    std::string lit = scene_with_sphere_material(R"({"type": "mirror"})");
    const std::string light = R"({"type": "lambertian", "albedo": [0, 0, 0], "emission": [5, 5, 5]})";
    lit.replace(lit.find(light), light.size(),
                R"({"type": "principled", "base_color": [0.2, 0.2, 0.2], "metallic": 0, "roughness": 0.5, "emission": [1, 2, 3]})");
    EXPECT_EQ(parse_scene_json(lit, "test.json").materials[1].emission, glm::vec3(1, 2, 3));
    const SceneDescription plain = parse_scene_json(
        scene_with_sphere_material(R"({"type": "principled", "base_color": [1, 1, 1], "metallic": 0, "roughness": 1})"), "test.json");
    EXPECT_FLOAT_EQ(plain.materials[2].ior, 1.5f);

    const auto render = [](const std::string& material) {
        return test::render_film(parse_scene_json(scene_with_sphere_material(material), "test.json"), Integrator::wavefront).film;
    };
    const Film mirror = render(R"({"type": "mirror"})");
    EXPECT_TRUE(mirror == render(R"({"type": "principled", "base_color": [1, 1, 1], "metallic": 1, "roughness": 0})"));
    EXPECT_FALSE(mirror == render(R"({"type": "principled", "base_color": [1, 1, 1], "metallic": 0.99, "roughness": 0})"));
    const Film gold = render(R"({"type": "conductor", "f0": [1, 0.77, 0.34], "roughness": 0.3})");
    EXPECT_TRUE(gold == render(R"({"type": "principled", "base_color": [1, 0.77, 0.34], "metallic": 1, "roughness": 0.3})"));
}


TEST(PrincipledSceneFile, RefusesBadValuesNamingTheField) {
    const std::string ok = R"("type": "principled", "base_color": [0.5, 0.5, 0.5], )";
    expect_refused("{" + ok + R"("metallic": 1.5, "roughness": 0.5})", "materials.ball.metallic: must be in [0, 1], got 1.5");
    expect_refused("{" + ok + R"("metallic": -0.1, "roughness": 0.5})", "materials.ball.metallic: must be in [0, 1]");
    expect_refused("{" + ok + R"("metallic": 0, "roughness": 2})", "materials.ball.roughness: must be in [0, 1], got 2");
    expect_refused("{" + ok + R"("metallic": 0, "roughness": 0.5, "ior": 0})", "materials.ball.ior: must be positive");
    expect_refused("{" + ok + R"("metallic": 0, "roughness": 0.5, "ior": -1.5})", "materials.ball.ior: must be positive");
    expect_refused("{" + ok + R"("metallic": 0, "roughness": 0.5, "f0": [1, 1, 1]})", "f0");
    expect_refused("{" + ok + R"("roughness": 0.5})", "materials.ball.metallic: required key is missing");
    expect_refused("{" + ok + R"("metallic": 0})", "materials.ball.roughness: required key is missing");
    expect_refused(R"({"type": "principled", "metallic": 0, "roughness": 0.5})", "materials.ball.base_color: required key is missing");
    expect_refused(R"({"type": "principled", "base_color": [1.2, 0, 0], "metallic": 0, "roughness": 0.5})",
                   "materials.ball.base_color[0]: must be in [0, 1]");
    expect_refused("{" + ok + R"("metallic": 0, "roughness": 0.5, "emission": [-1, 0, 0]})", "materials.ball.emission[0]");
}

}  // namespace
}  // namespace wt
