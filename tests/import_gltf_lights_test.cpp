// glTF's KHR_lights_punctual through the scene loader: point, spot and directional lights placed
// by their nodes' transforms and the shape's, photometric units to radiometric at 683 lm/W, a
// spot's cone angles, range noted and ignored, and bad lights refused naming the file.

#include <cmath>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "import_gltf_files.h"

namespace {

using wt::LightDescription;
using wt::LightType;
using wt::SceneDescription;
using Json = nlohmann::json;

using GltfLights = wt::test::ImportTest;

constexpr double kPi = 3.14159265358979323846;

// One triangle (the file must have a surface) and the given lights and light-placing nodes
// after the mesh's node 0.
std::string gltf_with_lights(const Json& lights, const Json& light_nodes) {
    wt::test::GltfFile f;
    f.primitive({{"attributes", {{"POSITION", f.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}}}});
    Json j = f.json("data:application/octet-stream;base64," + wt::test::base64(f.bin()));
    Json nodes = {{{"mesh", 0}}};
    Json roots = {0};
    for (const Json& n : light_nodes) {
        roots.push_back(nodes.size());
        nodes.push_back(n);
    }
    j["nodes"] = nodes;
    j["scenes"] = {{{"nodes", roots}}};
    j["extensionsUsed"] = {"KHR_lights_punctual"};
    j["extensions"] = {{"KHR_lights_punctual", {{"lights", lights}}}};
    return j.dump();
}

Json placing(int light, const Json& transform = Json::object()) {
    Json n = transform;
    n["extensions"] = {{"KHR_lights_punctual", {{"light", light}}}};
    return n;
}

void expect_vec3_near(const glm::vec3& v, glm::dvec3 expected, double tolerance = 1e-5) {
    EXPECT_NEAR(v.x, expected.x, tolerance);
    EXPECT_NEAR(v.y, expected.y, tolerance);
    EXPECT_NEAR(v.z, expected.z, tolerance);
}

TEST_F(GltfLights, PointSpotAndDirectionalBecomeTheLightsListInWatts) {
    const double s = std::sqrt(0.5);
    const Json lights = {
        {{"type", "point"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 683.0 * 2.0}, {"range", 10.0}},
        {{"type", "spot"}, {"intensity", 683.0}, {"spot", {{"innerConeAngle", 0.25}, {"outerConeAngle", 0.5}}}},
        {{"type", "directional"}, {"color", {0.0, 1.0, 0.0}}, {"intensity", 683.0 * 3.0}}};
    // Point at (1, 2, 3); the spot at (0, 0, 4) turned 90 degrees about x (its -z to +y) and
    // scaled (which changes nothing of its light); the sun turned 90 degrees about y (-z to -x).
    const Json nodes = {placing(0, {{"translation", {1, 2, 3}}}),
                        placing(1, {{"translation", {0, 0, 4}}, {"rotation", {s, 0, 0, s}}, {"scale", {3, 3, 3}}}),
                        placing(2, {{"rotation", {0, s, 0, s}}})};
    write("lit.gltf", gltf_with_lights(lights, nodes));
    // The shape's transform moves the lights with the triangles: translate by (10, 0, 0).
    const SceneDescription d = load_file("lit.gltf", R"(, "transform": {"translate": [10, 0, 0]})");
    ASSERT_EQ(d.lights.size(), 3u);

    const LightDescription& point = d.lights[0];
    EXPECT_EQ(point.type, LightType::point);
    expect_vec3_near(point.position, {11, 2, 3});
    expect_vec3_near(point.intensity, {2.0, 1.0, 0.5});  // candela / 683 lm/W: W/sr

    const LightDescription& spot = d.lights[1];
    EXPECT_EQ(spot.type, LightType::spot);
    expect_vec3_near(spot.position, {10, 0, 4});
    expect_vec3_near(spot.direction, {0, 1, 0});
    expect_vec3_near(spot.intensity, {1, 1, 1});
    EXPECT_NEAR(spot.cone_degrees, 2.0 * 0.5 * 180.0 / kPi, 1e-4);  // full angle from the outer half angle
    EXPECT_NEAR(spot.blend, 0.5, 1e-6);  // 1 - inner / outer: the inner cone's half angle is 0.25

    const LightDescription& sun = d.lights[2];
    EXPECT_EQ(sun.type, LightType::directional);
    expect_vec3_near(sun.direction, {-1, 0, 0});
    expect_vec3_near(sun.irradiance, {0, 3, 0});  // lux / 683 lm/W: W/m²
    EXPECT_EQ(sun.angle_degrees, 0.0f);

    bool range_noted = false;
    for (const std::string& n : d.notes) range_noted |= n.find("range is ignored") != std::string::npos;
    EXPECT_TRUE(range_noted);
}

TEST_F(GltfLights, TheSceneFilesOwnListComesFirstAndNodesPlacingALightTwiceGiveTwoLights) {
    write("two.gltf", gltf_with_lights({{{"type", "point"}, {"intensity", 683.0}}},
                                       {placing(0, {{"translation", {0, 0, 1}}}), placing(0, {{"translation", {0, 0, 2}}})}));
    const SceneDescription d = wt::parse_scene_json(
        R"({"camera": {"eye": [-5, 0, 0], "look_at": [0, 0, 0]}, "materials": )" + std::string(kMaterials) +
            R"(, "shapes": [{"type": "mesh_file", "file": "two.gltf", "material": "white"}],
             "lights": [{"type": "environment", "radiance": [1, 1, 1]}]})",
        path("scene.json"));
    ASSERT_EQ(d.lights.size(), 3u);
    EXPECT_EQ(d.lights[0].type, LightType::environment);
    expect_vec3_near(d.lights[1].position, {0, 0, 1});
    expect_vec3_near(d.lights[2].position, {0, 0, 2});
}

TEST_F(GltfLights, BadLightsAreRefusedNamingTheFileAndTheLight) {
    const auto refused = [&](const Json& light, const std::string& expected) {
        write("bad.gltf", gltf_with_lights(Json::array({light}), Json::array({placing(0)})));
        const std::string e = error_for("bad.gltf");
        EXPECT_NE(e.find("bad.gltf"), std::string::npos) << e;
        EXPECT_NE(e.find("light 0"), std::string::npos) << e;
        EXPECT_NE(e.find(expected), std::string::npos) << e;
    };
    refused({{"type", "point"}, {"intensity", -1.0}}, "intensity");
    refused({{"type", "point"}, {"color", {1.0, -1.0, 0.0}}}, "color");
    refused({{"type", "spot"}, {"spot", {{"innerConeAngle", 0.5}, {"outerConeAngle", 0.5}}}}, "cone angles");
    refused({{"type", "spot"}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 2.0}}}}, "cone angles");
    // A node naming a light the file does not have.
    write("missing.gltf", gltf_with_lights(Json::array({{{"type", "point"}}}), Json::array({placing(3)})));
    const std::string e = error_for("missing.gltf");
    EXPECT_NE(e.find("light 3: does not exist"), std::string::npos) << e;
}

TEST_F(GltfLights, ALightOfIntensityZeroIsLeftOutWithANote) {
    write("dark.gltf", gltf_with_lights(Json::array({{{"type", "point"}, {"intensity", 0.0}}}), Json::array({placing(0)})));
    const SceneDescription d = load_file("dark.gltf");
    EXPECT_TRUE(d.lights.empty());
    bool noted = false;
    for (const std::string& n : d.notes) noted |= n.find("emits nothing") != std::string::npos;
    EXPECT_TRUE(noted);
}

}  // namespace
