// The scene file's "lights" list: what it reads, and every bad input refused naming its field.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/film/image_output.h"
#include "core/scene/scene.h"
#include "scene_test_helpers.h"

namespace {

using wt::LightType;

std::string with_lights(const std::string& lights_json) {
    return mutated([&](Json& j) { j["lights"] = Json::parse(lights_json); });
}

// A w x h map file in the test's temporary directory, every texel `value` but (1, 0)'s `odd`.
std::string map_file(const std::string& name, float value, float odd, int w = 4, int h = 2) {
    const std::string path = (std::filesystem::temp_directory_path() / ("wavetrace_lights_test_" + name)).string();
    std::vector<float> rgb(std::size_t(w * h * 3), value);
    rgb[3 * 1 + 1] = odd;
    wt::write_image(path, w, h, rgb);
    return path;
}

TEST(SceneLights, ReadsEveryType) {
    const std::string map = map_file("sky.exr", 0.5f, 2.0f);
    const auto d = parse_scene_json(with_lights(R"([
        {"type": "environment", "file": ")" + map + R"(", "strength": 2, "rotate_degrees": 90},
        {"type": "point", "position": [1, 2, 3], "intensity": [4, 5, 6]},
        {"type": "spot", "position": [0, 0, 5], "direction": [0, 0, -2], "intensity": [1, 1, 1], "cone_degrees": 60, "blend": 0.25},
        {"type": "directional", "direction": [0, 0, -1], "irradiance": [3, 3, 3], "angle_degrees": 0.53}])"),
                                    kSource);
    ASSERT_EQ(d.lights.size(), 4u);
    EXPECT_EQ(d.lights[0].type, LightType::environment);
    ASSERT_TRUE(d.lights[0].map);
    EXPECT_EQ(d.lights[0].map->width, 4);
    EXPECT_EQ(d.lights[0].map->rgb[4], 2.0f);
    EXPECT_EQ(d.lights[0].strength, 2.0f);
    EXPECT_EQ(d.lights[0].rotate_degrees, 90.0f);
    EXPECT_EQ(d.lights[1].intensity, glm::vec3(4, 5, 6));
    EXPECT_EQ(d.lights[2].direction, glm::vec3(0, 0, -1));  // normalized
    EXPECT_EQ(d.lights[2].cone_degrees, 60.0f);
    EXPECT_EQ(d.lights[2].blend, 0.25f);
    EXPECT_EQ(d.lights[3].angle_degrees, 0.53f);
    const wt::Scene scene = wt::build_scene(d);
    EXPECT_FALSE(scene.listed_lights.empty());
    // The valid scene's quad light is one entry of the selection.
    EXPECT_GT(scene.listed_lights.area_probability(), 0.0f);
    EXPECT_LT(scene.listed_lights.area_probability(), 1.0f);
    std::filesystem::remove(map);
}

TEST(SceneLights, WithoutTheListNothingIsBuilt) {
    const wt::Scene scene = wt::build_scene(parse_scene_json(kValidScene, kSource));
    EXPECT_TRUE(scene.listed_lights.empty());
    EXPECT_EQ(scene.lights.pdf_area(), scene.lights.pdf_area_alone());
}

TEST(SceneLights, RefusesBadInputNamingTheField) {
    expect_scene_error(with_lights(R"({"type": "point"})"), "lights: expected an array");
    expect_scene_error(with_lights(R"([{"type": "area"}])"), "lights[0].type: unknown light type");
    expect_scene_error(with_lights(R"([{"type": "point", "position": [0, 0, 0], "intensity": [0, 0, 0]}])"),
                       "lights[0].intensity: a light must emit something");
    expect_scene_error(with_lights(R"([{"type": "point", "position": [0, 0, 0], "intensity": [1, -1, 1]}])"),
                       "lights[0].intensity[1]: must be non-negative");
    expect_scene_error(with_lights(R"([{"type": "point", "intensity": [1, 1, 1]}])"), "lights[0]");
    expect_scene_error(with_lights(R"([{"type": "point", "position": [0, 0, 0], "intensity": [1, 1, 1], "cone_degrees": 3}])"),
                       "cone_degrees");
    const std::string spot = R"({"type": "spot", "position": [0, 0, 0], "direction": [0, 0, -1], "intensity": [1, 1, 1], )";
    expect_scene_error(with_lights("[" + spot + R"("cone_degrees": 0}])"), "lights[0].cone_degrees: must be in (0, 180]");
    expect_scene_error(with_lights("[" + spot + R"("cone_degrees": 181}])"), "lights[0].cone_degrees: must be in (0, 180]");
    expect_scene_error(with_lights("[" + spot + R"("cone_degrees": 30, "blend": 2}])"), "lights[0].blend: must be in [0, 1]");
    expect_scene_error(with_lights(R"([{"type": "directional", "direction": [0, 0, 0], "irradiance": [1, 1, 1]}])"),
                       "lights[0].direction: must be a non-zero vector");
    expect_scene_error(
        with_lights(R"([{"type": "directional", "direction": [0, 0, -1], "irradiance": [1, 1, 1], "angle_degrees": -1}])"),
        "lights[0].angle_degrees: must be in [0, 180]");
    expect_scene_error(with_lights(R"([{"type": "environment"}])"), "lights[0]");
    expect_scene_error(with_lights(R"([{"type": "environment", "radiance": [1, 1, 1], "strength": 2}])"),
                       "lights[0].strength: applies to a map file only");
    expect_scene_error(with_lights(R"([{"type": "environment", "radiance": [1, 1, 1]}, {"type": "environment", "radiance": [1, 1, 1]}])"),
                       "lights[1]: a scene has at most one environment");
}

TEST(SceneLights, RefusesAMissingOrUnreadableMap) {
    expect_scene_error(with_lights(R"([{"type": "environment", "file": "/nonexistent/sky.exr"}])"),
                       "lights[0].file: cannot use the environment map");
    const std::string path = (std::filesystem::temp_directory_path() / "wavetrace_lights_test_garbage.exr").string();
    std::FILE* f = std::fopen(path.c_str(), "wb");
    std::fputs("not an image", f);
    std::fclose(f);
    expect_scene_error(with_lights(R"([{"type": "environment", "file": ")" + path + R"("}])"),
                       "lights[0].file: cannot use the environment map");
    std::filesystem::remove(path);
}

TEST(SceneLights, RefusesNegativeAndNonFiniteTexels) {
    const std::string negative = map_file("negative.exr", 0.5f, -1.0f);
    expect_scene_error(with_lights(R"([{"type": "environment", "file": ")" + negative + R"("}])"),
                       "negative or non-finite texel at (1, 0)");
    std::filesystem::remove(negative);
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        const std::string path = map_file("nonfinite.exr", 0.5f, bad);
        expect_scene_error(with_lights(R"([{"type": "environment", "file": ")" + path + R"("}])"), "lights[0].file:");
        std::filesystem::remove(path);
    }
}

}  // namespace
