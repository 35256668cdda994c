#pragma once
// A small valid scene file and the ways tests edit it, for the scene-loader tests: every test
// of a bad input starts from something valid and changes one thing.

#include <functional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/scene_file/scene_loader.h"

namespace {

using wt::parse_scene_json;
using wt::SceneError;
using Json = nlohmann::ordered_json;

const std::string kSource = "test.json";

// Small but complete: every material type, every shape type. Material names are deliberately not
// in alphabetical order, so the test of material order means something.
const std::string kValidScene = R"({
  "camera": {"eye": [0, 0, 0], "look_at": [1, 0, 0], "up": [0, 0, 1], "fov_degrees": 60},
  "render": {"width": 4, "height": 3, "spp": 2},
  "materials": {
    "white": {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]},
    "lamp": {"type": "lambertian", "albedo": [0, 0, 0], "emission": [5, 5, 5]},
    "rough": {"type": "oren_nayar", "albedo": [0.5, 0.5, 0.5], "sigma": 0.3},
    "chrome": {"type": "mirror", "reflectance": [0.9, 0.9, 0.9]},
    "glass": {"type": "glass", "ior": 1.5}
  },
  "shapes": [
    {"type": "sphere", "center": [5, 0, 0], "radius": 1, "material": "glass"},
    {"type": "quad", "vertices": [[4, -1, 2], [4, 1, 2], [6, 1, 2], [6, -1, 2]], "material": "lamp"},
    {"type": "mesh", "vertices": [[3, -2, -2], [3, 2, -2], [7, 0, -2]], "triangles": [[0, 2, 1]], "material": "white"}
  ]
})";

// The valid scene, edited as JSON.
[[maybe_unused]] std::string mutated(const std::function<void(Json&)>& edit) {
    Json j = Json::parse(kValidScene);
    edit(j);
    return j.dump();
}

// The valid scene, edited as text: for what a JSON value cannot express (syntax errors,
// overflowing literals, repeated keys, 2.0 versus 2).
[[maybe_unused]] std::string replaced(const std::string& from, const std::string& to) {
    std::string text = kValidScene;
    const std::size_t at = text.find(from);
    if (at == std::string::npos) {
        ADD_FAILURE() << "test bug: " << from << " is not in the valid scene";
        return text;
    }
    return text.replace(at, from.size(), to);
}

void expect_scene_error(const std::string& json_text, const std::string& expected_substring) {
    try {
        parse_scene_json(json_text, kSource);
        ADD_FAILURE() << "no SceneError; expected one containing: " << expected_substring;
    } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(kSource + ":", 0), 0u) << "message does not start with the source name: " << message;
        EXPECT_NE(message.find(expected_substring), std::string::npos)
            << "message: " << message << "\nexpected to contain: " << expected_substring;
    }
}

}  // namespace
