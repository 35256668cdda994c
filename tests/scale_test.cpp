// The hexroom scaled down to 0.1 mm rooms, up to 100 km rooms, and moved 100 km from the
// origin must render the same image: ray offsets scale with the coordinates (ray_offset.h),
// so there is no acne at large scales and no light leaking at small ones.

#include <gtest/gtest.h>

#include "render_helpers.h"
#include "test_scenes.h"

namespace wt {
namespace {

SceneDescription transformed(SceneDescription d, float scale, glm::vec3 offset) {
    auto move = [&](glm::vec3 p) { return p * scale + offset; };
    for (TriangleMesh& m : d.meshes)
        for (glm::vec3& v : m.vertices) v = move(v);
    for (Sphere& s : d.spheres) {
        s.center = move(s.center);
        s.radius *= scale;
    }
    d.camera.eye = move(d.camera.eye);
    d.camera.look_at = move(d.camera.look_at);
    return d;
}

struct ScaleCase {
    const char* name;
    float scale;
    glm::vec3 offset;
    AccuracySettings accuracy;
};

class SceneScale : public ::testing::TestWithParam<ScaleCase> {};

TEST_P(SceneScale, RendersTheSameImageAsTheOriginal) {
    const ScaleCase c = GetParam();
    SceneDescription original = test::hexroom(20, 20, 64, /*seed=*/1);
    original.settings.accuracy = c.accuracy;
    SceneDescription moved = transformed(test::hexroom(20, 20, 64, /*seed=*/2), c.scale, c.offset);
    moved.settings.accuracy = c.accuracy;
    const test::RenderedFilm a = test::render_film(original, Integrator::wavefront);
    const test::RenderedFilm b = test::render_film(moved, Integrator::wavefront);
    EXPECT_EQ(b.result.counts.nonfinite_samples, 0u);
    test::expect_films_agree(a.film, b.film, [&](uint32_t p) { return std::string(c.name) + " pixel " + std::to_string(p); });
}

const AccuracySettings kDefault{};
const AccuracySettings kAccurate{TriangleTest::watertight, SphereTest::cancellation_free, FresnelModel::exact};

INSTANTIATE_TEST_SUITE_P(
    Hexroom, SceneScale,
    ::testing::Values(ScaleCase{"tiny", 1e-4f, glm::vec3(0.0f), kDefault}, ScaleCase{"huge", 1e4f, glm::vec3(0.0f), kDefault},
                      ScaleCase{"far", 1.0f, glm::vec3(1e5f, -1e5f, 1e5f), kDefault},
                      ScaleCase{"tiny_accurate", 1e-4f, glm::vec3(0.0f), kAccurate},
                      ScaleCase{"far_accurate", 1.0f, glm::vec3(1e5f, -1e5f, 1e5f), kAccurate}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace wt
