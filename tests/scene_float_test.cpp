// Scene values that are fine in double but not in the float the renderer computes in: each
// rendered a black image with exit 0 ("NaN/Inf samples 0"). The loader must refuse them,
// naming the field, and still accept the nearest values that work.

#include <string>

#include <gtest/gtest.h>

#include "core/camera/camera.h"
#include "core/scene/scene.h"
#include "scene_test_helpers.h"

namespace {

const std::string kCamera = "\"camera\": {\"eye\": [0, 0, 0], \"look_at\": [1, 0, 0], \"up\": [0, 0, 1], \"fov_degrees\": 60}";
const std::string kLight = "\"vertices\": [[4, -1, 2], [4, 1, 2], [6, 1, 2], [6, -1, 2]], \"material\": \"lamp\"";
const std::string kSigma = "\"sigma\": 0.3";

std::string with_camera(const std::string& eye, const std::string& look_at, const std::string& up) {
    return replaced(kCamera, "\"camera\": {\"eye\": " + eye + ", \"look_at\": " + look_at + ", \"up\": " + up + "}");
}

// A quad light at x from x0 to x0 + w, y from -w/2 to w/2, facing down (z = 2).
std::string with_light(const std::string& x0, const std::string& x1, const std::string& y) {
    return replaced(kLight, "\"vertices\": [[" + x0 + ", -" + y + ", 2], [" + x0 + ", " + y + ", 2], [" + x1 + ", " + y +
                                ", 2], [" + x1 + ", -" + y + ", 2]], \"material\": \"lamp\"");
}

bool camera_basis_is_finite(const wt::SceneDescription& scene) {
    const wt::CameraBasis b = wt::camera_basis(scene.camera);
    for (const glm::vec3& v : {b.forward, b.right, b.up})
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
    return true;
}

TEST(FloatValidation, AViewDirectionTooShortForFloatIsRefused) {
    expect_scene_error(with_camera("[0, 0, 0]", "[1e-30, 0, 0]", "[0, 0, 1]"),
                       "camera.look_at: look_at - eye = [1e-30, 0, 0] cannot be normalised in 32-bit float");
    EXPECT_TRUE(camera_basis_is_finite(parse_scene_json(with_camera("[0, 0, 0]", "[1e-15, 0, 0]", "[0, 0, 1]"), kSource)));
}

TEST(FloatValidation, AnUpVectorTooLongOrTooShortForFloatIsRefused) {
    expect_scene_error(with_camera("[0, 0, 0]", "[1, 0, 0]", "[0, 0, 1e20]"), "camera.up: cannot be used in 32-bit float");
    expect_scene_error(with_camera("[0, 0, 0]", "[1, 0, 0]", "[0, 0, 1e-30]"), "camera.up: cannot be used in 32-bit float");
    EXPECT_TRUE(camera_basis_is_finite(parse_scene_json(with_camera("[0, 0, 0]", "[1, 0, 0]", "[0, 0, 1e15]"), kSource)));
    EXPECT_TRUE(camera_basis_is_finite(parse_scene_json(with_camera("[0, 0, 0]", "[1, 0, 0]", "[0, 0, 1e-15]"), kSource)));
}

TEST(FloatValidation, AnEyeAndLookAtAtTheEndsOfTheFloatRangeAreRefused) {
    expect_scene_error(with_camera("[-3e38, 0, 0]", "[3e38, 0, 0]", "[0, 0, 1]"),
                       "camera.look_at: look_at - eye overflows a 32-bit float");
    expect_scene_error(with_camera("[3e38, 0, 0]", "[-3e38, 0, 0]", "[0, 0, 1]"),
                       "camera.look_at: look_at - eye overflows a 32-bit float");
    // glm::length squares in float: past about 1.8e19 the view direction does not normalise.
    expect_scene_error(with_camera("[-1e38, 0, 0]", "[1e38, 0, 0]", "[0, 0, 1]"), "cannot be normalised in 32-bit float");
    EXPECT_TRUE(camera_basis_is_finite(parse_scene_json(with_camera("[-1e18, 0, 0]", "[1e18, 0, 0]", "[0, 0, 1]"), kSource)));
}

TEST(FloatValidation, ALightWhoseAreaUnderflowsInFloatIsRefused) {
    // Legs of 1e-12: in double the quad is fine (|cross| 1e-24 against 1e-12 x 1e-24 squared
    // edges), in float |cross| squares to 1e-48, which underflows, and the light table dropped it.
    expect_scene_error(with_light("0", "1e-12", "5e-13"), "shapes[1].triangles[0]: degenerate light");
    expect_scene_error(with_light("0", "1e-12", "5e-13"), "has zero area in 32-bit float");
    const wt::Scene scene = wt::build_scene(parse_scene_json(with_light("0", "1e-6", "5e-7"), kSource));
    EXPECT_GT(scene.lights.total_area(), 0.0f);
}

TEST(FloatValidation, ALightWhoseAreaOverflowsInFloatIsRefused) {
    // |cross| of 1e40 is infinite; so is 1e38, whose square glm::length takes in float.
    expect_scene_error(with_light("-5e19", "5e19", "5e19"), "shapes[1].triangles[0]: light too large");
    expect_scene_error(with_light("-5e18", "5e18", "5e18"), "shapes[1].triangles[0]: light too large");
    const wt::Scene scene = wt::build_scene(parse_scene_json(with_light("-5e8", "5e8", "5e8"), kSource));
    EXPECT_TRUE(std::isfinite(scene.lights.total_area()));
}

TEST(FloatValidation, AnOrenNayarSigmaWhoseSquareOverflowsIsRefused) {
    expect_scene_error(replaced(kSigma, "\"sigma\": 1e20"), "materials.rough.sigma: is too large for the Oren-Nayar coefficients");
    EXPECT_NO_THROW(parse_scene_json(replaced(kSigma, "\"sigma\": 1e19"), kSource));
}

}  // namespace
