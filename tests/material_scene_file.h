#pragma once
// What the scene-file tests of the rough and principled materials share: a small lit scene whose
// sphere's material is the JSON text under test, and the check that a material is refused with
// a message naming its field.

#include <string>

#include <gtest/gtest.h>

#include "core/scene_file/scene_error.h"
#include "core/scene_file/scene_loader.h"

namespace wt::test {

// Materials "wall", "light" (a quad emitting 5) and "ball" (the sphere: `material`), in that order.
inline std::string scene_with_sphere_material(const std::string& material) {
    return R"({
      "camera": {"eye": [0, 0, 0], "look_at": [1, 0, 0]},
      "render": {"width": 12, "height": 10, "spp": 4},
      "materials": {
        "wall": {"type": "lambertian", "albedo": [0.6, 0.5, 0.4]},
        "light": {"type": "lambertian", "albedo": [0, 0, 0], "emission": [5, 5, 5]},
        "ball": )" + material + R"(
      },
      "shapes": [
        {"type": "sphere", "center": [3, 0, 0], "radius": 1, "material": "ball"},
        {"type": "quad", "vertices": [[5, -3, -2], [5, 3, -2], [5, 3, 3], [5, -3, 3]], "material": "wall"},
        {"type": "quad", "vertices": [[4, -1, 2.5], [2, -1, 2.5], [2, 1, 2.5], [4, 1, 2.5]], "material": "light"}
      ]
    })";
}

// The scene with `material` on the sphere is refused with a message containing `expected`.
inline void expect_refused(const std::string& material, const std::string& expected) {
    try {
        parse_scene_json(scene_with_sphere_material(material), "test.json");
        ADD_FAILURE() << "no SceneError for " << material;
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
}

}  // namespace wt::test
