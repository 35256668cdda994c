#include "core/scene_file/scene_loader.h"
#include "core/scene/scene.h"
#include "scene_test_helpers.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#ifndef WT_SCENES_DIR
#error "WT_SCENES_DIR must be defined as the path of the scenes/ directory (a string literal)"
#endif

namespace {

using wt::Material;
using wt::MaterialType;
using wt::SceneDescription;
using wt::SceneError;
using wt::parse_scene_json;
using wt::TriangleMesh;
using wt::TriangleTest;
using wt::SphereTest;
using wt::FresnelModel;
using wt::LightSampling;
using wt::SamplerKind;
using Json = nlohmann::ordered_json;

glm::vec3 triangle_normal(const TriangleMesh& mesh, std::size_t t) {
    const auto& tri = mesh.triangles[t];
    const glm::vec3 v0 = mesh.vertices[tri[0]];
    return glm::cross(mesh.vertices[tri[1]] - v0, mesh.vertices[tri[2]] - v0);
}

glm::vec3 triangle_centroid(const TriangleMesh& mesh, std::size_t t) {
    const auto& tri = mesh.triangles[t];
    return (mesh.vertices[tri[0]] + mesh.vertices[tri[1]] + mesh.vertices[tri[2]]) / 3.0f;
}

std::size_t triangle_count(const SceneDescription& scene) {
    std::size_t n = 0;
    for (const TriangleMesh& mesh : scene.meshes) n += mesh.triangles.size();
    return n;
}

void expect_vec3_eq(const glm::vec3& actual, const glm::vec3& expected) {
    EXPECT_FLOAT_EQ(actual.x, expected.x);
    EXPECT_FLOAT_EQ(actual.y, expected.y);
    EXPECT_FLOAT_EQ(actual.z, expected.z);
}

// ---------------------------------------------------------------------------------------------
// Valid input

TEST(SceneLoader, ParsesTheValidScene) {
    const SceneDescription scene = parse_scene_json(kValidScene, kSource);

    expect_vec3_eq(scene.camera.eye, {0, 0, 0});
    expect_vec3_eq(scene.camera.look_at, {1, 0, 0});
    expect_vec3_eq(scene.camera.up, {0, 0, 1});
    EXPECT_FLOAT_EQ(scene.camera.fov_degrees, 60.0f);

    const wt::RenderSettings defaults;
    EXPECT_EQ(scene.settings.width, 4);
    EXPECT_EQ(scene.settings.height, 3);
    EXPECT_EQ(scene.settings.spp, 2);
    EXPECT_EQ(scene.settings.shadow_rays, defaults.shadow_rays);
    EXPECT_EQ(scene.settings.seed, defaults.seed);
    EXPECT_EQ(scene.settings.max_bounces, defaults.max_bounces);
    EXPECT_EQ(scene.settings.rr_start_bounce, defaults.rr_start_bounce);

    ASSERT_EQ(scene.materials.size(), 5u);
    EXPECT_EQ(scene.materials[0].name, "white");  // file order, not alphabetical
    EXPECT_EQ(scene.materials[1].name, "lamp");
    EXPECT_EQ(scene.materials[2].name, "rough");
    EXPECT_EQ(scene.materials[3].name, "chrome");
    EXPECT_EQ(scene.materials[4].name, "glass");
    EXPECT_EQ(scene.materials[0].type, MaterialType::lambertian);
    expect_vec3_eq(scene.materials[0].albedo, glm::vec3(0.5f));
    EXPECT_FALSE(scene.materials[0].is_emissive());
    expect_vec3_eq(scene.materials[1].emission, glm::vec3(5.0f));
    EXPECT_TRUE(scene.materials[1].is_emissive());
    EXPECT_EQ(scene.materials[2].type, MaterialType::oren_nayar);
    EXPECT_FLOAT_EQ(scene.materials[2].sigma, 0.3f);
    EXPECT_EQ(scene.materials[3].type, MaterialType::mirror);
    expect_vec3_eq(scene.materials[3].reflectance, glm::vec3(0.9f));
    EXPECT_EQ(scene.materials[4].type, MaterialType::glass);
    EXPECT_FLOAT_EQ(scene.materials[4].ior, 1.5f);

    ASSERT_EQ(scene.spheres.size(), 1u);
    expect_vec3_eq(scene.spheres[0].center, {5, 0, 0});
    EXPECT_FLOAT_EQ(scene.spheres[0].radius, 1.0f);
    EXPECT_EQ(scene.spheres[0].material, 4u);

    ASSERT_EQ(scene.meshes.size(), 2u);
    const TriangleMesh& quad = scene.meshes[0];
    EXPECT_EQ(quad.material, 1u);
    ASSERT_EQ(quad.vertices.size(), 4u);
    expect_vec3_eq(quad.vertices[3], {6, -1, 2});
    ASSERT_EQ(quad.triangles.size(), 2u);
    EXPECT_EQ(quad.triangles[0], (std::array<uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(quad.triangles[1], (std::array<uint32_t, 3>{0, 2, 3}));
    const TriangleMesh& mesh = scene.meshes[1];
    EXPECT_EQ(mesh.material, 0u);
    ASSERT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.triangles[0], (std::array<uint32_t, 3>{0, 2, 1}));
}

TEST(SceneLoader, RenderSectionIsOptional) {
    const SceneDescription scene = parse_scene_json(mutated([](Json& j) { j.erase("render"); }), kSource);
    const wt::RenderSettings defaults;
    EXPECT_EQ(scene.settings.width, defaults.width);
    EXPECT_EQ(scene.settings.height, defaults.height);
    EXPECT_EQ(scene.settings.spp, defaults.spp);
    EXPECT_EQ(scene.settings.shadow_rays, defaults.shadow_rays);
    EXPECT_EQ(scene.settings.seed, defaults.seed);
    EXPECT_EQ(scene.settings.max_bounces, defaults.max_bounces);
    EXPECT_EQ(scene.settings.rr_start_bounce, defaults.rr_start_bounce);
}

TEST(SceneLoader, CameraUpAndFovAreOptional) {
    const SceneDescription scene = parse_scene_json(mutated([](Json& j) {
        j["camera"].erase("up");
        j["camera"].erase("fov_degrees");
    }), kSource);
    expect_vec3_eq(scene.camera.up, {0, 0, 1});
    EXPECT_FLOAT_EQ(scene.camera.fov_degrees, 90.0f);
}

TEST(SceneLoader, MirrorReflectanceDefaultsToOne) {
    const SceneDescription scene =
        parse_scene_json(mutated([](Json& j) { j["materials"]["chrome"].erase("reflectance"); }), kSource);
    expect_vec3_eq(scene.materials[3].reflectance, glm::vec3(1.0f));
}

TEST(SceneLoader, ZeroEmissionIsAllowedAndIsNotALight) {
    // Allowed on a sphere, and on a zero-area triangle: neither is a light.
    const SceneDescription scene = parse_scene_json(mutated([](Json& j) {
        j["materials"]["white"]["emission"] = {0, 0, 0};
        j["shapes"][0]["material"] = "white";
        j["shapes"][2]["triangles"].push_back({0, 1, 1});
    }), kSource);
    EXPECT_FALSE(scene.materials[0].is_emissive());
    EXPECT_EQ(scene.meshes[1].triangles.size(), 2u);
}

TEST(SceneLoader, RangeLimitsAreInclusive) {
    const SceneDescription scene = parse_scene_json(mutated([](Json& j) {
        j["render"] = {{"width", 65536}, {"height", 1}, {"spp", 1 << 20}, {"shadow_rays", 1024},
                       {"max_bounces", 1024}, {"rr_start_bounce", 0}};
    }), kSource);
    EXPECT_EQ(scene.settings.width, 65536);
    EXPECT_EQ(scene.settings.height, 1);
    EXPECT_EQ(scene.settings.spp, 1 << 20);
    EXPECT_EQ(scene.settings.shadow_rays, 1024);
    EXPECT_EQ(scene.settings.max_bounces, 1024);
    EXPECT_EQ(scene.settings.rr_start_bounce, 0);
}

TEST(SceneLoader, SeedTakesTheFullUint64Range) {
    const SceneDescription scene =
        parse_scene_json(replaced(R"("spp": 2)", R"("spp": 2, "seed": 18446744073709551615)"), kSource);
    EXPECT_EQ(scene.settings.seed, UINT64_MAX);
}

TEST(SceneLoader, SectionOrderDoesNotMatter) {
    Json reordered;
    const Json original = Json::parse(kValidScene);
    for (const char* key : {"shapes", "materials", "render", "camera"}) reordered[key] = original[key];
    const SceneDescription scene = parse_scene_json(reordered.dump(), kSource);
    EXPECT_EQ(scene.meshes.size(), 2u);
    EXPECT_EQ(scene.spheres[0].material, 4u);
}

// A quad is marked a parallelogram exactly when v2 = v1 + v3 - v0 as written; a planar
// trapezoid is still a valid quad, just not one.
TEST(SceneLoader, QuadIsMarkedParallelogramOnlyWhenItIsOne) {
    EXPECT_TRUE(parse_scene_json(kValidScene, kSource).meshes[0].parallelogram);
    const SceneDescription trapezoid =
        parse_scene_json(replaced("[6, 1, 2], [6, -1, 2]", "[6, 1.5, 2], [6, -1, 2]"), kSource);
    EXPECT_FALSE(trapezoid.meshes[0].parallelogram);
    EXPECT_FALSE(trapezoid.meshes[1].parallelogram) << "a mesh is never one";
}

// ---------------------------------------------------------------------------------------------
// The reference scenes

class HexRoom : public ::testing::Test {
protected:
    void SetUp() override { scene = wt::load_scene_file(std::string(WT_SCENES_DIR) + "/hexroom.json"); }

    const Material& material_of(const TriangleMesh& mesh) const { return scene.materials[mesh.material]; }
    bool is_light(const TriangleMesh& mesh) const { return material_of(mesh).is_emissive(); }
    bool is_tetra(const TriangleMesh& mesh) const { return material_of(mesh).name == "orange"; }
    bool is_room(const TriangleMesh& mesh) const { return !is_light(mesh) && !is_tetra(mesh); }

    SceneDescription scene;
};

TEST_F(HexRoom, Counts) {
    EXPECT_EQ(scene.materials.size(), 11u);
    // 6 wall quads, floor, ceiling, light, tetrahedron
    ASSERT_EQ(scene.meshes.size(), 10u);
    EXPECT_EQ(scene.spheres.size(), 4u);
    EXPECT_EQ(triangle_count(scene), 6u * 2 + 4 + 4 + 2 + 4);

    std::size_t room = 0, lights = 0, tetras = 0, room_triangles = 0;
    for (const TriangleMesh& mesh : scene.meshes) {
        if (is_room(mesh)) {
            ++room;
            room_triangles += mesh.triangles.size();
        }
        lights += is_light(mesh);
        tetras += is_tetra(mesh);
    }
    EXPECT_EQ(room, 8u);
    EXPECT_EQ(room_triangles, 20u);
    EXPECT_EQ(lights, 1u);
    EXPECT_EQ(tetras, 1u);
}

// Moller-Trumbore scenes store the 7 rectangles (6 walls, the light) as parallelograms ahead
// of the 12 triangles; the watertight test gets all 26 triangles.
TEST_F(HexRoom, QuadsBecomeParallelogramsOnlyForMollerTrumbore) {
    std::size_t parallelogram_quads = 0;
    for (const TriangleMesh& mesh : scene.meshes) parallelogram_quads += mesh.parallelogram;
    EXPECT_EQ(parallelogram_quads, 7u);

    scene.settings.accuracy.triangles = TriangleTest::moller_trumbore;
    const wt::Scene mt = wt::build_scene(scene);
    EXPECT_EQ(mt.triangles.parallelogram_count, 7u);
    EXPECT_EQ(mt.triangles.size(), 7u + 12u);
    // The first wall: v0 = (-3, 0, -5), spanned by v1 - v0 and v3 - v0.
    expect_vec3_eq(mt.triangles.vertex0(0), {-3, 0, -5});
    expect_vec3_eq(mt.triangles.edge1(0), {3, 6, 0});
    expect_vec3_eq(mt.triangles.edge2(0), {0, 0, 10});

    scene.settings.accuracy.triangles = TriangleTest::watertight;
    const wt::Scene watertight = wt::build_scene(scene);
    EXPECT_EQ(watertight.triangles.parallelogram_count, 0u);
    EXPECT_EQ(watertight.triangles.size(), 26u);
}

TEST_F(HexRoom, RoomNormalsPointInward) {
    const glm::vec3 interior(5.0f, 0.0f, 0.0f);
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const TriangleMesh& mesh = scene.meshes[m];
        if (!is_room(mesh)) continue;
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            const glm::vec3 to_interior = interior - mesh.vertices[mesh.triangles[t][0]];
            EXPECT_GT(glm::dot(triangle_normal(mesh, t), to_interior), 0.0f)
                << "mesh " << m << " (" << material_of(mesh).name << ") triangle " << t;
        }
    }
}

TEST_F(HexRoom, TetrahedronNormalsPointOutward) {
    for (const TriangleMesh& mesh : scene.meshes) {
        if (!is_tetra(mesh)) continue;
        ASSERT_EQ(mesh.vertices.size(), 4u);
        ASSERT_EQ(mesh.triangles.size(), 4u);
        const glm::vec3 centroid = (mesh.vertices[0] + mesh.vertices[1] + mesh.vertices[2] + mesh.vertices[3]) / 4.0f;
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
            EXPECT_GT(glm::dot(triangle_normal(mesh, t), triangle_centroid(mesh, t) - centroid), 0.0f) << "triangle " << t;
    }
}

TEST_F(HexRoom, LightFacesDown) {
    for (const TriangleMesh& mesh : scene.meshes) {
        if (!is_light(mesh)) continue;
        expect_vec3_eq(material_of(mesh).emission, glm::vec3(20.0f));
        expect_vec3_eq(material_of(mesh).albedo, glm::vec3(0.0f));
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            const glm::vec3 n = glm::normalize(triangle_normal(mesh, t));
            EXPECT_NEAR(n.x, 0.0f, 1e-6f);
            EXPECT_NEAR(n.y, 0.0f, 1e-6f);
            EXPECT_NEAR(n.z, -1.0f, 1e-6f);
        }
        for (const glm::vec3& v : mesh.vertices) EXPECT_FLOAT_EQ(v.z, 4.99f);
    }
}

TEST_F(HexRoom, SpheresCameraAndSettings) {
    ASSERT_EQ(scene.spheres.size(), 4u);
    const Material& glass = scene.materials[scene.spheres[0].material];
    EXPECT_EQ(glass.type, MaterialType::glass);
    EXPECT_FLOAT_EQ(glass.ior, 1.5f);
    EXPECT_FLOAT_EQ(scene.spheres[0].radius, 1.5f);
    EXPECT_EQ(scene.spheres[1].material, scene.spheres[0].material);
    EXPECT_EQ(scene.materials[scene.spheres[2].material].type, MaterialType::lambertian);
    const Material& rough = scene.materials[scene.spheres[3].material];
    EXPECT_EQ(rough.type, MaterialType::oren_nayar);
    EXPECT_FLOAT_EQ(rough.sigma, 0.9f);

    expect_vec3_eq(scene.camera.eye, {-1, 0, 0});
    expect_vec3_eq(scene.camera.look_at, {0, 0, 0});
    EXPECT_FLOAT_EQ(scene.camera.fov_degrees, 90.0f);
    EXPECT_EQ(scene.settings.width, 800);
    EXPECT_EQ(scene.settings.height, 800);
    EXPECT_EQ(scene.settings.spp, 64);
    EXPECT_EQ(scene.settings.shadow_rays, 1);
    EXPECT_EQ(scene.settings.seed, 0u);
}

TEST(Furnace, ClosedCubeOfOneEmissiveGreyMaterialFacingInward) {
    const SceneDescription scene = wt::load_scene_file(std::string(WT_SCENES_DIR) + "/furnace.json");
    ASSERT_EQ(scene.materials.size(), 1u);
    expect_vec3_eq(scene.materials[0].albedo, glm::vec3(0.5f));
    expect_vec3_eq(scene.materials[0].emission, glm::vec3(1.0f));
    EXPECT_TRUE(scene.spheres.empty());
    ASSERT_EQ(scene.meshes.size(), 6u);
    glm::vec3 normal_sum(0.0f);
    for (const TriangleMesh& mesh : scene.meshes) {
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            const glm::vec3 n = triangle_normal(mesh, t);
            EXPECT_GT(glm::dot(n, -triangle_centroid(mesh, t)), 0.0f);
            normal_sum += n;
        }
        for (const glm::vec3& v : mesh.vertices) EXPECT_FLOAT_EQ(glm::length(v), std::sqrt(3.0f));
    }
    expect_vec3_eq(normal_sum, glm::vec3(0.0f));  // closed: the area vectors cancel
    EXPECT_EQ(scene.settings.width, 32);
    EXPECT_EQ(scene.settings.height, 32);
    EXPECT_EQ(scene.settings.spp, 16);
    expect_vec3_eq(scene.camera.eye, {0, 0, 0});
    expect_vec3_eq(glm::normalize(scene.camera.look_at - scene.camera.eye), {1, 0, 0});
}

// ---------------------------------------------------------------------------------------------
// Files

TEST(LoadSceneFile, MissingFileNamesThePathAndTheReason) {
    const std::string path = std::string(WT_SCENES_DIR) + "/no_such_scene.json";
    try {
        wt::load_scene_file(path);
        ADD_FAILURE() << "no SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": cannot open: No such file or directory");
    }
}

TEST(LoadSceneFile, DirectoryIsNotReadable) {
    try {
        wt::load_scene_file(WT_SCENES_DIR);
        ADD_FAILURE() << "no SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(std::string(WT_SCENES_DIR) + ": cannot", 0), 0u) << e.what();
    }
}

// ---------------------------------------------------------------------------------------------
// JSON syntax

TEST(SceneErrors, SyntaxErrorGivesLineAndColumn) {
    expect_scene_error("{\n  \"camera\": ,\n}", "test.json:2:13: JSON syntax error: ");
}

TEST(SceneErrors, SyntaxErrorInTheValidSceneGivesItsLine) {
    expect_scene_error(replaced(R"("radius": 1,)", R"("radius": 1,,)"), "test.json:12:57: JSON syntax error");
}

TEST(SceneErrors, TruncatedText) {
    expect_scene_error(kValidScene.substr(0, kValidScene.size() - 1), "JSON syntax error");
}

TEST(SceneErrors, EmptyText) { expect_scene_error("", "test.json:1:1: JSON syntax error"); }

TEST(SceneErrors, TopLevelNotAnObject) { expect_scene_error("[1, 2]", "(top level): expected an object, got [1,2]"); }

TEST(SceneErrors, DuplicateMaterialName) {
    expect_scene_error(replaced(R"("lamp": {)", R"("white": {"type": "glass", "ior": 1.2}, "lamp": {)"),
                       "materials.white: duplicate material name \"white\"");
}

TEST(SceneErrors, DuplicateKey) {
    expect_scene_error(replaced(R"("radius": 1,)", R"("radius": 1, "radius": 2,)"), "shapes[0].radius: duplicate key");
}

// ---------------------------------------------------------------------------------------------
// Unknown and missing keys

TEST(SceneErrors, UnknownTopLevelKey) {
    // "lights" is a section now; "light" is the typo it most likely comes as.
    expect_scene_error(mutated([](Json& j) { j["light"] = Json::array(); }),
                       "light: unknown key (allowed: camera, render, materials, meshes, shapes, lights)");
}

TEST(SceneErrors, UnknownCameraKey) {
    expect_scene_error(mutated([](Json& j) { j["camera"]["fov"] = 60; }),
                       "camera.fov: unknown key (allowed: eye, look_at, up, fov_degrees, projection, width_world, aperture_radius, "
                       "focus_distance, focus_on)");
}

TEST(SceneErrors, UnknownRenderKey) {
    expect_scene_error(mutated([](Json& j) { j["render"]["samples"] = 4; }),
                       "render.samples: unknown key (allowed: width, height, spp, shadow_rays, seed, max_bounces, "
                       "rr_start_bounce, triangle_test, sphere_test, fresnel, multiple_scattering, sampler, light_sampling, light_selection, clamp_indirect, caustics, "
                       "light_paths_per_pixel, photon_radius, adaptive_threshold, adaptive_min_spp, filter, filter_width)");
}

TEST(SceneErrors, UnknownAccuracyChoice) {
    expect_scene_error(mutated([](Json& j) { j["render"]["triangle_test"] = "exact"; }),
                       "render.triangle_test: must be one of \"moller_trumbore\", \"watertight\", got string \"exact\"");
    expect_scene_error(mutated([](Json& j) { j["render"]["sphere_test"] = 3; }), "render.sphere_test: expected a string");
    expect_scene_error(mutated([](Json& j) { j["render"]["fresnel"] = "fast"; }), "render.fresnel: must be one of");
}

TEST(SceneLoader, ReadsAccuracyOptions) {
    const SceneDescription d = parse_scene_json(
        mutated([](Json& j) {
            j["render"]["triangle_test"] = "watertight";
            j["render"]["sphere_test"] = "cancellation_free";
            j["render"]["fresnel"] = "exact";
        }),
        "test.json");
    EXPECT_EQ(d.settings.accuracy.triangles, TriangleTest::watertight);
    EXPECT_EQ(d.settings.accuracy.spheres, SphereTest::cancellation_free);
    EXPECT_EQ(d.settings.accuracy.fresnel, FresnelModel::exact);
}

TEST(SceneLoader, ReadsEstimatorOptions) {
    const SceneDescription defaults = parse_scene_json(mutated([](Json&) {}), "test.json");
    EXPECT_EQ(defaults.settings.estimator.sampler, SamplerKind::stratified);
    EXPECT_EQ(defaults.settings.estimator.light_sampling, LightSampling::nee);
    EXPECT_EQ(defaults.settings.estimator.clamp_indirect, 0.0f);
    const SceneDescription d = parse_scene_json(
        mutated([](Json& j) {
            j["render"]["sampler"] = "sobol";
            j["render"]["light_sampling"] = "mis";
            j["render"]["clamp_indirect"] = 2.5;
        }),
        "test.json");
    EXPECT_EQ(d.settings.estimator.sampler, SamplerKind::sobol);
    EXPECT_EQ(d.settings.estimator.light_sampling, LightSampling::mis);
    EXPECT_EQ(d.settings.estimator.clamp_indirect, 2.5f);
    EXPECT_EQ(parse_scene_json(mutated([](Json& j) { j["render"]["sampler"] = "independent"; }), "test.json")
                  .settings.estimator.sampler,
              SamplerKind::independent);
}

TEST(SceneErrors, BadEstimatorOption) {
    expect_scene_error(mutated([](Json& j) { j["render"]["sampler"] = "halton"; }),
                       "render.sampler: must be one of \"independent\", \"stratified\", \"sobol\", got string \"halton\"");
    expect_scene_error(mutated([](Json& j) { j["render"]["light_sampling"] = "bsdf"; }),
                       "render.light_sampling: must be one of \"nee\", \"mis\"");
    expect_scene_error(mutated([](Json& j) { j["render"]["light_sampling"] = true; }), "render.light_sampling: expected a string");
    expect_scene_error(mutated([](Json& j) { j["render"]["clamp_indirect"] = -1; }),
                       "render.clamp_indirect: must be non-negative (0 turns the clamp off), got -1");
    expect_scene_error(mutated([](Json& j) { j["render"]["clamp_indirect"] = "high"; }), "render.clamp_indirect: expected a number");
}

TEST(SceneLoader, ReadsAdaptiveSampling) {
    const SceneDescription defaults = parse_scene_json(mutated([](Json&) {}), "test.json");
    EXPECT_FALSE(defaults.settings.adaptive.enabled()) << "off by default";
    EXPECT_EQ(defaults.settings.adaptive.min_spp, 16);
    const SceneDescription d = parse_scene_json(
        mutated([](Json& j) {
            j["render"]["adaptive_threshold"] = 0.05;
            j["render"]["adaptive_min_spp"] = 32;
        }),
        "test.json");
    EXPECT_TRUE(d.settings.adaptive.enabled());
    EXPECT_EQ(d.settings.adaptive.threshold, 0.05f);
    EXPECT_EQ(d.settings.adaptive.min_spp, 32);
}

TEST(SceneErrors, BadAdaptiveSampling) {
    expect_scene_error(mutated([](Json& j) { j["render"]["adaptive_threshold"] = -0.1; }),
                       "render.adaptive_threshold: must be non-negative (0 turns adaptive sampling off), got -0.1");
    expect_scene_error(mutated([](Json& j) { j["render"]["adaptive_threshold"] = "low"; }),
                       "render.adaptive_threshold: expected a number");
    expect_scene_error(mutated([](Json& j) { j["render"]["adaptive_min_spp"] = 1; }),
                       "render.adaptive_min_spp: must be an integer in [2, 1048576], got 1");
    expect_scene_error(mutated([](Json& j) { j["render"]["adaptive_min_spp"] = 16.5; }),
                       "render.adaptive_min_spp: expected an integer (no decimal point or exponent)");
    expect_scene_error(mutated([](Json& j) { j["render"]["adaptive_min_spp"] = 2000000; }),
                       "render.adaptive_min_spp: must be an integer in [2, 1048576], got 2000000");
}

TEST(SceneErrors, UnknownMaterialKey) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["white"]["sigma"] = 0.2; }),
                       "materials.white.sigma: unknown key for a lambertian material (allowed: type, albedo, emission)");
}

TEST(SceneErrors, UnknownShapeKey) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][0]["radus"] = 2; }),
                       "shapes[0].radus: unknown key for a sphere (allowed: type, center, radius, material)");
}

TEST(SceneErrors, MissingCamera) {
    expect_scene_error(mutated([](Json& j) { j.erase("camera"); }), "camera: required key is missing");
}

TEST(SceneErrors, MissingMaterials) {
    expect_scene_error(mutated([](Json& j) { j.erase("materials"); }), "materials: required key is missing");
}

TEST(SceneErrors, MissingShapes) {
    expect_scene_error(mutated([](Json& j) { j.erase("shapes"); }), "shapes: required key is missing");
}

TEST(SceneErrors, MissingEye) {
    expect_scene_error(mutated([](Json& j) { j["camera"].erase("eye"); }), "camera.eye: required key is missing");
}

TEST(SceneErrors, MissingAlbedo) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["white"].erase("albedo"); }),
                       "materials.white.albedo: required key is missing");
}

TEST(SceneErrors, MissingSigma) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["rough"].erase("sigma"); }),
                       "materials.rough.sigma: required key is missing");
}

TEST(SceneErrors, MissingIor) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["glass"].erase("ior"); }),
                       "materials.glass.ior: required key is missing");
}

TEST(SceneErrors, MissingMaterialType) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["white"].erase("type"); }),
                       "materials.white.type: required key is missing (one of lambertian, oren_nayar, mirror, glass, conductor, rough_glass, principled)");
}

TEST(SceneErrors, MissingShapeType) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][1].erase("type"); }),
                       "shapes[1].type: required key is missing (one of quad, mesh, sphere, mesh_file, instance)");
}

TEST(SceneErrors, MissingShapeMaterial) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][2].erase("material"); }),
                       "shapes[2].material: required key is missing");
}

TEST(SceneErrors, MissingRadius) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][0].erase("radius"); }), "shapes[0].radius: required key is missing");
}

TEST(SceneErrors, MissingTriangles) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][2].erase("triangles"); }),
                       "shapes[2].triangles: required key is missing");
}

// ---------------------------------------------------------------------------------------------
// Wrong types and vector lengths

TEST(SceneErrors, StringWhereANumberIsExpected) {
    expect_scene_error(mutated([](Json& j) { j["camera"]["fov_degrees"] = "60"; }),
                       "camera.fov_degrees: expected a number, got string \"60\"");
}

TEST(SceneErrors, BooleanWhereANumberIsExpected) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][0]["radius"] = true; }),
                       "shapes[0].radius: expected a number, got true");
}

TEST(SceneErrors, NullWhereANumberIsExpected) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["glass"]["ior"] = nullptr; }),
                       "materials.glass.ior: expected a number, got null");
}

TEST(SceneErrors, ArrayWhereAnObjectIsExpected) {
    expect_scene_error(mutated([](Json& j) { j["camera"] = Json::array(); }),
                       "camera: expected an object, got an empty array");
}

TEST(SceneErrors, MaterialsNotAnObject) {
    expect_scene_error(mutated([](Json& j) { j["materials"] = Json::array({1}); }),
                       "materials: expected an object, got [1]");
}

TEST(SceneErrors, MaterialNotAnObject) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["white"] = "lambertian"; }),
                       "materials.white: expected an object, got string \"lambertian\"");
}

TEST(SceneErrors, NumberWhereAStringIsExpected) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["white"]["type"] = 3; }),
                       "materials.white.type: expected a string, got 3");
}

TEST(SceneErrors, ShapesNotAnArray) {
    expect_scene_error(mutated([](Json& j) { j["shapes"] = Json::object(); }), "shapes: expected an array, got an object");
}

TEST(SceneErrors, ShapeNotAnObject) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][1] = 7; }), "shapes[1]: expected an object, got 7");
}

TEST(SceneErrors, VectorTooShort) {
    expect_scene_error(mutated([](Json& j) { j["camera"]["eye"] = {0, 0}; }),
                       "camera.eye: expected an array of 3 numbers, got [0,0]");
}

TEST(SceneErrors, VectorTooLong) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][0]["center"] = {5, 0, 0, 1}; }),
                       "shapes[0].center: expected an array of 3 numbers, got [5,0,0,1]");
}

TEST(SceneErrors, VectorNotAnArray) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["white"]["albedo"] = 0.5; }),
                       "materials.white.albedo: expected an array of 3 numbers, got 0.5");
}

TEST(SceneErrors, VectorElementNotANumber) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][0]["center"][1] = "0"; }),
                       "shapes[0].center[1]: expected a number, got string \"0\"");
}

TEST(SceneErrors, MeshVertexWrongLength) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][2]["vertices"][1] = {3, 2}; }),
                       "shapes[2].vertices[1]: expected an array of 3 numbers, got [3,2]");
}

// ---------------------------------------------------------------------------------------------
// Numbers that do not fit

// nlohmann 3.11 refuses such literals (out_of_range 406) instead of returning inf, and says
// neither where nor in which field; the message must still name the field.
TEST(SceneErrors, OverflowingLiteral) {
    expect_scene_error(replaced(R"("radius": 1,)", R"("radius": 1e999,)"),
                       "shapes[0].radius: must be a finite number, got 1e999 (too large for a double)");
}

TEST(SceneErrors, OverflowingLiteralInANestedArray) {
    expect_scene_error(replaced("[7, 0, -2]", "[7, -1e999, -2]"), "shapes[2].vertices[2][1]: must be a finite number, got -1e999");
}

TEST(SceneErrors, OverflowingIor) {
    expect_scene_error(replaced(R"("ior": 1.5)", R"("ior": 1e400)"), "materials.glass.ior: must be a finite number, got 1e400");
}

TEST(SceneErrors, TooLargeForAFloat) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][0]["radius"] = 1e39; }),
                       "shapes[0].radius: is too large for a 32-bit float, got 1e+39");
}

// ---------------------------------------------------------------------------------------------
// Materials

TEST(SceneErrors, UnknownMaterialType) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["white"]["type"] = "plastic"; }),
                       "materials.white.type: unknown material type (allowed: lambertian, oren_nayar, mirror, glass, conductor, rough_glass, principled), "
                       "got string \"plastic\"");
}

TEST(SceneErrors, EmptyMaterialName) {
    expect_scene_error(mutated([](Json& j) { j["materials"][""] = j["materials"]["white"]; }),
                       "materials: material names must not be empty");
}

TEST(SceneErrors, NegativeAlbedo) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["white"]["albedo"][0] = -0.1; }),
                       "materials.white.albedo[0]: must be in [0, 1], got -0.1");
}

TEST(SceneErrors, AlbedoAboveOne) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["rough"]["albedo"][2] = 1.2; }),
                       "materials.rough.albedo[2]: must be in [0, 1], got 1.2");
}

TEST(SceneErrors, NegativeEmission) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["lamp"]["emission"][1] = -1; }),
                       "materials.lamp.emission[1]: must be non-negative, got -1");
}

TEST(SceneErrors, ReflectanceAboveOne) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["chrome"]["reflectance"] = {1, 1.5, 1}; }),
                       "materials.chrome.reflectance[1]: must be in [0, 1], got 1.5");
}

TEST(SceneErrors, NegativeReflectance) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["chrome"]["reflectance"] = {-1, 1, 1}; }),
                       "materials.chrome.reflectance[0]: must be in [0, 1], got -1");
}

TEST(SceneErrors, ZeroIor) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["glass"]["ior"] = 0; }),
                       "materials.glass.ior: must be positive, got 0");
}

TEST(SceneErrors, NegativeIor) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["glass"]["ior"] = -1.5; }),
                       "materials.glass.ior: must be positive, got -1.5");
}

TEST(SceneErrors, NegativeSigma) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["rough"]["sigma"] = -0.1; }),
                       "materials.rough.sigma: must be non-negative, got -0.1");
}

TEST(SceneErrors, EmissionOnMirror) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["chrome"]["emission"] = {1, 1, 1}; }),
                       "materials.chrome.emission: emission is not supported on mirror materials");
}

TEST(SceneErrors, EmissionOnGlass) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["glass"]["emission"] = {1, 1, 1}; }),
                       "materials.glass.emission: emission is not supported on glass materials");
}

TEST(SceneErrors, KeyOfAnotherMaterialType) {
    expect_scene_error(mutated([](Json& j) { j["materials"]["glass"]["albedo"] = {1, 1, 1}; }),
                       "materials.glass.albedo: unknown key for a glass material (allowed: type, ior)");
}

// ---------------------------------------------------------------------------------------------
// Shapes

TEST(SceneErrors, NoShapes) {
    expect_scene_error(mutated([](Json& j) { j["shapes"] = Json::array(); }),
                       "shapes: a scene needs at least one shape, got an empty array");
}

TEST(SceneErrors, UnknownShapeType) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][0]["type"] = "cube"; }),
                       "shapes[0].type: unknown shape type (allowed: quad, mesh, sphere, mesh_file, instance), got string \"cube\"");
}

TEST(SceneErrors, MissingMaterialIsNamed) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][0]["material"] = "glas"; }),
                       "shapes[0].material: no material named \"glas\" (defined: white, lamp, rough, chrome, glass)");
}

TEST(SceneErrors, NegativeRadius) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][0]["radius"] = -1; }), "shapes[0].radius: must be positive, got -1");
}

TEST(SceneErrors, ZeroRadius) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][0]["radius"] = 0; }), "shapes[0].radius: must be positive, got 0");
}

TEST(SceneErrors, EmissiveSphere) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][0]["material"] = "lamp"; }),
                       "shapes[0].material: emissive spheres are not supported; use a mesh");
}

TEST(SceneErrors, TriangleIndexOutOfRange) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][2]["triangles"][0] = {0, 2, 3}; }),
                       "shapes[2].triangles[0][2]: must be an integer in [0, 2], got 3");
}

TEST(SceneErrors, NegativeTriangleIndex) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][2]["triangles"][0][0] = -1; }),
                       "shapes[2].triangles[0][0]: must be an integer in [0, 2], got -1");
}

TEST(SceneErrors, FractionalTriangleIndex) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][2]["triangles"][0][1] = 1.5; }),
                       "shapes[2].triangles[0][1]: expected an integer");
}

TEST(SceneErrors, TriangleWithTwoIndices) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][2]["triangles"].push_back({0, 1}); }),
                       "shapes[2].triangles[1]: expected an array of 3 vertex indices, got [0,1]");
}

TEST(SceneErrors, MeshWithNoTriangles) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][2]["triangles"] = Json::array(); }),
                       "shapes[2].triangles: a mesh needs at least one triangle, got an empty array");
}

TEST(SceneErrors, MeshWithTooFewVertices) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][2]["vertices"].erase(2); }),
                       "shapes[2].vertices: a mesh needs at least 3 vertices, got 2");
}

TEST(SceneErrors, DegenerateEmissiveTriangle) {
    expect_scene_error(mutated([](Json& j) {
        j["shapes"][2]["material"] = "lamp";
        j["shapes"][2]["triangles"].push_back({0, 1, 1});
    }), "shapes[2].triangles[1]: degenerate light: emissive triangle 1 has zero area");
}

TEST(SceneErrors, CollinearEmissiveTriangle) {
    expect_scene_error(mutated([](Json& j) {
        j["shapes"][2]["material"] = "lamp";
        j["shapes"][2]["vertices"].push_back({5, 0, -2});
        j["shapes"][2]["triangles"].push_back({0, 3, 1});  // (3,-2), (5,0), (3,2): fine
        j["shapes"][2]["triangles"].push_back({2, 3, 0});  // (7,0), (5,0), (3,-2): fine
        j["shapes"][2]["vertices"].push_back({1, -4, -2});
        j["shapes"][2]["triangles"].push_back({4, 0, 3});  // (1,-4), (3,-2), (5,0): on one line
    }), "shapes[2].triangles[3]: degenerate light: emissive triangle 3 has zero area");
}

TEST(SceneErrors, QuadWithThreeVertices) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][1]["vertices"].erase(3); }),
                       "shapes[1].vertices: a quad needs exactly 4 vertices");
}

TEST(SceneErrors, DegenerateQuad) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][1]["vertices"][2] = {4, 3, 2}; }),
                       "shapes[1].vertices: degenerate quad: its triangle 0 (v0, v1, v2) has zero area");
}

TEST(SceneErrors, NonPlanarQuad) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][1]["vertices"][3] = {6, -1, 2.5}; }),
                       "shapes[1].vertices: non-planar quad: v3 is 0.5 from the plane of v0, v1, v2");
}

TEST(SceneErrors, QuadVerticesOutOfOrder) {
    expect_scene_error(mutated([](Json& j) {
        std::swap(j["shapes"][1]["vertices"][2], j["shapes"][1]["vertices"][3]);
    }), "shapes[1].vertices: quad vertices are not in order around its boundary");
}

TEST(SceneErrors, QuadAllowsOnlyItsKeys) {
    expect_scene_error(mutated([](Json& j) { j["shapes"][1]["triangles"] = {{0, 1, 2}}; }),
                       "shapes[1].triangles: unknown key for a quad (allowed: type, vertices, material)");
}

// ---------------------------------------------------------------------------------------------
// Render settings

TEST(SceneErrors, WidthZero) {
    expect_scene_error(mutated([](Json& j) { j["render"]["width"] = 0; }),
                       "render.width: must be an integer in [1, 65536], got 0");
}

TEST(SceneErrors, WidthTooLarge) {
    expect_scene_error(mutated([](Json& j) { j["render"]["width"] = 65537; }),
                       "render.width: must be an integer in [1, 65536], got 65537");
}

TEST(SceneErrors, HeightZero) {
    expect_scene_error(mutated([](Json& j) { j["render"]["height"] = 0; }),
                       "render.height: must be an integer in [1, 65536], got 0");
}

TEST(SceneErrors, HeightNegative) {
    expect_scene_error(mutated([](Json& j) { j["render"]["height"] = -800; }),
                       "render.height: must be an integer in [1, 65536], got -800");
}

TEST(SceneErrors, WidthAsString) {
    expect_scene_error(mutated([](Json& j) { j["render"]["width"] = "800"; }),
                       "render.width: expected an integer, got string \"800\"");
}

TEST(SceneErrors, SppZero) {
    expect_scene_error(mutated([](Json& j) { j["render"]["spp"] = 0; }),
                       "render.spp: must be an integer in [1, 1048576], got 0");
}

TEST(SceneErrors, SppTooLarge) {
    expect_scene_error(mutated([](Json& j) { j["render"]["spp"] = (1 << 20) + 1; }),
                       "render.spp: must be an integer in [1, 1048576], got 1048577");
}

TEST(SceneErrors, SppFractional) {
    expect_scene_error(mutated([](Json& j) { j["render"]["spp"] = 2.5; }),
                       "render.spp: expected an integer (no decimal point or exponent), got 2.5");
}

TEST(SceneErrors, SppWrittenAsAFloat) {
    expect_scene_error(replaced(R"("spp": 2)", R"("spp": 2.0)"),
                       "render.spp: expected an integer (no decimal point or exponent), got 2.0");
}

TEST(SceneErrors, ShadowRaysZero) {
    expect_scene_error(mutated([](Json& j) { j["render"]["shadow_rays"] = 0; }),
                       "render.shadow_rays: must be an integer in [1, 1024], got 0");
}

TEST(SceneErrors, ShadowRaysTooLarge) {
    expect_scene_error(mutated([](Json& j) { j["render"]["shadow_rays"] = 1025; }),
                       "render.shadow_rays: must be an integer in [1, 1024], got 1025");
}

TEST(SceneErrors, MaxBouncesZero) {
    expect_scene_error(mutated([](Json& j) { j["render"]["max_bounces"] = 0; }),
                       "render.max_bounces: must be an integer in [1, 1024], got 0");
}

TEST(SceneErrors, MaxBouncesTooLarge) {
    expect_scene_error(mutated([](Json& j) { j["render"]["max_bounces"] = 1025; }),
                       "render.max_bounces: must be an integer in [1, 1024], got 1025");
}

TEST(SceneErrors, RussianRouletteStartNegative) {
    expect_scene_error(mutated([](Json& j) { j["render"]["rr_start_bounce"] = -1; }),
                       "render.rr_start_bounce: must be an integer in [0, 2147483647], got -1");
}

TEST(SceneErrors, SeedNegative) {
    expect_scene_error(mutated([](Json& j) { j["render"]["seed"] = -1; }),
                       "render.seed: must be an integer in [0, 18446744073709551615], got -1");
}

TEST(SceneErrors, SeedAboveUint64) {
    expect_scene_error(replaced(R"("spp": 2)", R"("spp": 2, "seed": 18446744073709551616)"),
                       "render.seed: must be an integer in [0, 18446744073709551615], got 1.8446744073709552e+19");
}

TEST(SceneErrors, SeedFractional) {
    expect_scene_error(mutated([](Json& j) { j["render"]["seed"] = 0.5; }), "render.seed: expected an integer");
}

// ---------------------------------------------------------------------------------------------
// Camera

TEST(SceneErrors, EyeEqualsLookAt) {
    expect_scene_error(mutated([](Json& j) { j["camera"]["look_at"] = {0, 0, 0}; }),
                       "camera.look_at: must differ from camera.eye, got [0, 0, 0] for both");
}

TEST(SceneErrors, UpParallelToViewDirection) {
    expect_scene_error(mutated([](Json& j) { j["camera"]["up"] = {2, 0, 0}; }),
                       "camera.up: must not be parallel to the view direction");
}

TEST(SceneErrors, UpOppositeToViewDirection) {
    expect_scene_error(mutated([](Json& j) { j["camera"]["up"] = {-1, 0, 0}; }),
                       "camera.up: must not be parallel to the view direction");
}

TEST(SceneErrors, UpZero) {
    expect_scene_error(mutated([](Json& j) { j["camera"]["up"] = {0, 0, 0}; }), "camera.up: must be non-zero");
}

TEST(SceneErrors, FovZero) {
    expect_scene_error(mutated([](Json& j) { j["camera"]["fov_degrees"] = 0; }),
                       "camera.fov_degrees: must be in (0, 180) degrees, exclusive, got 0");
}

TEST(SceneErrors, Fov180) {
    expect_scene_error(mutated([](Json& j) { j["camera"]["fov_degrees"] = 180; }),
                       "camera.fov_degrees: must be in (0, 180) degrees, exclusive, got 180");
}

TEST(SceneErrors, FovNegative) {
    expect_scene_error(mutated([](Json& j) { j["camera"]["fov_degrees"] = -45.5; }),
                       "camera.fov_degrees: must be in (0, 180) degrees, exclusive, got -45.5");
}

}  // namespace
