// The cameras (core/camera/camera.h): the thin lens against the pinhole and against its own inverse,
// the orthographic window, the lens's sampler pattern, and the camera section's bad input.

#include <cmath>
#include <cstring>
#include <set>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/camera/camera.h"
#include "core/checkpoint/checkpoint_settings.h"
#include "core/scene/scene.h"
#include "core/sampling/samplers.h"
#include "camera_importance.h"
#include "scene_test_helpers.h"

namespace wt {
namespace {

CameraDescription lens_camera(float aperture) {
    CameraDescription d;
    d.eye = {0.3f, -1.0f, 0.5f};
    d.look_at = {1.0f, 0.2f, 0.1f};
    d.fov_degrees = 55.0f;
    d.aperture_radius = aperture;
    d.focus_distance = 2.5f;
    return d;
}

bool same_bits(const Ray& a, const Ray& b) {
    return std::memcmp(&a.origin, &b.origin, sizeof a.origin) == 0 && std::memcmp(&a.direction, &b.direction, sizeof a.direction) == 0;
}

TEST(ThinLens, ApertureZeroIsThePinholeBitForBit) {
    CameraDescription pinhole = lens_camera(0.0f);
    pinhole.focus_distance = 0.0f;
    const Camera a(pinhole, 40, 30), b(lens_camera(0.0f), 40, 30), lens(lens_camera(0.1f), 40, 30);
    EXPECT_FALSE(b.has_lens());
    int lens_differs = 0;
    for (int i = 0; i < 100; ++i) {
        const float x = 0.4f * float(i), y = 0.29f * float(i);
        const glm::vec2 u(float((i * 37) % 100) / 100.0f, float((i * 61) % 100) / 100.0f);
        EXPECT_TRUE(same_bits(a.generate_ray(x, y), b.generate_ray(x, y, u)));
        lens_differs += !same_bits(a.generate_ray(x, y), lens.generate_ray(x, y, u));
    }
    EXPECT_GE(lens_differs, 99);  // the other side: a real lens moves the rays (u = (0.5, 0.5) is its centre)
}

TEST(ThinLens, FilmPointThroughTheLensInvertsGenerateRay) {
    const int width = 40, height = 30;
    const Camera camera(lens_camera(0.2f), width, height);
    for (int i = 0; i < 400; ++i) {
        const float fx = float(width) * ((i * 37) % 200 + 0.5f) / 200.0f, fy = float(height) * ((i * 91) % 200 + 0.5f) / 200.0f;
        const glm::vec2 u(float((i * 53) % 97) / 97.0f, float((i * 29) % 89) / 89.0f);
        const Ray r = camera.generate_ray(fx, fy, u);
        EXPECT_EQ(r.origin, camera.lens_point(u));
        for (float t : {0.7f, 2.5f, 9.0f}) {  // before, on and beyond the plane of focus
            const auto p = camera.film_point_through_lens(r.origin + t * r.direction, r.origin, 0.0f);
            ASSERT_TRUE(p.has_value());
            EXPECT_NEAR(p->x, fx, 2e-3f);
            EXPECT_NEAR(p->y, fy, 2e-3f);
        }
        // On the plane of focus every lens point sees the point at the pinhole's film position: sharp.
        const Ray centre = camera.generate_ray(fx, fy);
        const glm::vec3 focused = centre.origin + (2.5f / glm::dot(centre.direction, camera.forward())) * centre.direction;
        const auto q = camera.film_point_through_lens(focused, r.origin, 0.0f);
        ASSERT_TRUE(q.has_value());
        EXPECT_NEAR(q->x, fx, 2e-3f);
        EXPECT_NEAR(q->y, fy, 2e-3f);
    }
}

// From any point of the lens, the importance integrates over the directions to one per pixel,
// as the pinhole's does from the eye (the lens's area cancels against its pdf).
TEST(ThinLens, ImportanceFromAnOffCentreLensPointIntegratesToThePixelCount) {
    const int width = 40, height = 30;
    const Camera camera(lens_camera(0.3f), width, height);
    const glm::vec3 lens = camera.lens_point({0.9f, 0.2f});
    EXPECT_GT(glm::length(lens - camera.eye()), 0.1f);
    const double total =
        test::importance_over_the_sphere([&](const glm::vec3& dir) { return camera.film_point_through_lens(lens + dir, lens, 0.0f); });
    EXPECT_NEAR(total, double(width * height), 0.01 * width * height);
    // Half a pixel left of the image: off the film, unless a margin widens it.
    const glm::vec3 beyond = lens + camera.generate_ray(-0.5f, 3.0f, {0.9f, 0.2f}).direction;
    EXPECT_FALSE(camera.film_point_through_lens(beyond, lens, 0.0f));
    EXPECT_TRUE(camera.film_point_through_lens(beyond, lens, 1.0f));
}

TEST(Orthographic, RaysAreParallelFromAWindowWidthWorldWide) {
    CameraDescription d = lens_camera(0.0f);
    d.projection = Projection::orthographic;
    d.width_world = 4.0f;
    const Camera camera(d, 40, 20);
    EXPECT_TRUE(camera.is_orthographic());
    const Ray left = camera.generate_ray(0.0f, 10.0f), right = camera.generate_ray(40.0f, 10.0f);
    const Ray top = camera.generate_ray(20.0f, 0.0f), bottom = camera.generate_ray(20.0f, 20.0f);
    EXPECT_EQ(left.direction, camera.forward());
    EXPECT_EQ(top.direction, camera.forward());
    EXPECT_NEAR(glm::length(right.origin - left.origin), 4.0f, 1e-5f);
    EXPECT_NEAR(glm::length(bottom.origin - top.origin), 2.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(right.origin - left.origin, camera.forward()), 0.0f, 1e-5f);
    EXPECT_FALSE(camera.film_point(d.look_at));  // nothing joins an orthographic camera
}

// The lens's own pattern: for the stratified and Sobol' samplers a pixel's first 16 lens points
// fall one in each cell of a 4 x 4 grid, and they are not the pixel offsets' pattern.
template <typename S>
void expect_stratified_lens(uint64_t seed, uint32_t pixel) {
    std::set<int> cells;
    int same_as_pixel = 0;
    for (uint32_t s = 0; s < 16; ++s) {
        const PathSeed path{S::key_of(seed, pixel, s), s};
        const glm::vec2 u = S::lens_position(path, seed, pixel);
        cells.insert(int(u.x * 4.0f) * 4 + int(u.y * 4.0f));
        const glm::vec2 o = S(path, 0, 1).pixel_offset(seed, pixel, s);
        same_as_pixel += int(o.x * 4.0f) == int(u.x * 4.0f) && int(o.y * 4.0f) == int(u.y * 4.0f);
    }
    EXPECT_EQ(cells.size(), 16u);
    EXPECT_LT(same_as_pixel, 16);
}

TEST(ThinLens, LensSamplesAreStratifiedPerPixel) {
    for (uint32_t pixel : {0u, 7u, 1234u}) {
        expect_stratified_lens<StratifiedSampler>(3, pixel);
        expect_stratified_lens<SobolSampler>(3, pixel);
    }
}

// --- the scene file's camera section ---

std::string with_camera(const std::function<void(Json&)>& edit) {
    return mutated([&](Json& j) { edit(j["camera"]); });
}

TEST(CameraSection, ReadsTheThinLensAndFocusOnAPoint) {
    const SceneDescription d = parse_scene_json(with_camera([](Json& c) {
        c["aperture_radius"] = 0.05;
        c["focus_on"] = {3, 7, 1};  // the view axis is +x from the origin: depth 3
    }), kSource);
    EXPECT_FLOAT_EQ(d.camera.aperture_radius, 0.05f);
    EXPECT_FLOAT_EQ(d.camera.focus_distance, 3.0f);
    const SceneDescription e = parse_scene_json(with_camera([](Json& c) { c["focus_distance"] = 2.5; }), kSource);
    EXPECT_FLOAT_EQ(e.camera.focus_distance, 2.5f);
    EXPECT_FLOAT_EQ(e.camera.aperture_radius, 0.0f);
    EXPECT_EQ(e.camera.projection, Projection::perspective);
}

TEST(CameraSection, OrthographicTurnsLightTracingOffUnlessAskedFor) {
    const std::string ortho = with_camera([](Json& c) {
        c.erase("fov_degrees");
        c["projection"] = "orthographic";
        c["width_world"] = 3;
    });
    const SceneDescription d = parse_scene_json(ortho, kSource);
    EXPECT_EQ(d.camera.projection, Projection::orthographic);
    EXPECT_FLOAT_EQ(d.camera.width_world, 3.0f);
    // The valid scene has a light and glass: with the pinhole it light-traces them, orthographic not.
    EXPECT_TRUE(light_traces_caustics(parse_scene_json(kValidScene, kSource)));
    EXPECT_FALSE(light_traces_caustics(d));
    Json j = Json::parse(ortho);
    j["render"]["caustics"] = "light_tracing";
    expect_scene_error(j.dump(), "render.caustics: \"light_tracing\" needs a perspective camera");
    j["render"]["caustics"] = "photons";
    expect_scene_error(j.dump(), "render.caustics: \"photons\" needs a perspective camera");
    j["render"]["caustics"] = "path";
    EXPECT_NO_THROW(parse_scene_json(j.dump(), kSource));
}

TEST(CameraSection, BadLensAndProjectionNameTheField) {
    expect_scene_error(with_camera([](Json& c) { c["aperture_radius"] = -0.1; }), "camera.aperture_radius: must be non-negative");
    expect_scene_error(with_camera([](Json& c) { c["aperture_radius"] = "wide"; }), "camera.aperture_radius");
    expect_scene_error(with_camera([](Json& c) { c["focus_distance"] = 0; }), "camera.focus_distance: must be greater than 0");
    expect_scene_error(with_camera([](Json& c) { c["focus_distance"] = -2; }), "camera.focus_distance: must be greater than 0");
    expect_scene_error(with_camera([](Json& c) { c["focus_on"] = {-1, 0, 0}; }), "camera.focus_on: must lie in front of the eye");
    expect_scene_error(with_camera([](Json& c) { c["focus_on"] = {0, 5, 0}; }), "camera.focus_on: must lie in front of the eye");
    expect_scene_error(with_camera([](Json& c) { c["focus_on"] = {1, 2}; }), "camera.focus_on");
    expect_scene_error(with_camera([](Json& c) {
        c["focus_on"] = {3, 0, 0};
        c["focus_distance"] = 3;
    }), "camera.focus_on: cannot be given with focus_distance");
    expect_scene_error(with_camera([](Json& c) { c["projection"] = "fisheye"; }),
                       "camera.projection: must be one of \"perspective\", \"orthographic\"");
    expect_scene_error(with_camera([](Json& c) { c["width_world"] = 2; }), "camera.width_world: is for \"projection\": \"orthographic\" only");
    const auto ortho = [](const std::function<void(Json&)>& more) {
        return with_camera([&](Json& c) {
            c.erase("fov_degrees");
            c["projection"] = "orthographic";
            c["width_world"] = 2;
            more(c);
        });
    };
    expect_scene_error(ortho([](Json& c) { c.erase("width_world"); }), "width_world");
    expect_scene_error(ortho([](Json& c) { c["width_world"] = 0; }), "camera.width_world: must be a positive number");
    expect_scene_error(ortho([](Json& c) { c["width_world"] = 1e39; }), "camera.width_world");
    expect_scene_error(ortho([](Json& c) { c["fov_degrees"] = 40; }), "camera.fov_degrees: is for the perspective camera");
    expect_scene_error(ortho([](Json& c) { c["aperture_radius"] = 0.1; }), "camera.aperture_radius: is for the perspective camera");
}

TEST(RenderSection, FilterAndItsWidth) {
    const auto with_render = [](const std::function<void(Json&)>& edit) { return mutated([&](Json& j) { edit(j["render"]); }); };
    EXPECT_TRUE(parse_scene_json(kValidScene, kSource).settings.filter.is_unit_box());
    const SceneDescription g = parse_scene_json(with_render([](Json& r) { r["filter"] = "gaussian"; }), kSource);
    EXPECT_EQ(g.settings.filter.kind, FilterKind::gaussian);
    EXPECT_FLOAT_EQ(g.settings.filter.width, 1.5f);
    const SceneDescription b = parse_scene_json(with_render([](Json& r) {
        r["filter"] = "blackman_harris";
        r["filter_width"] = 2;
    }), kSource);
    EXPECT_EQ(b.settings.filter.kind, FilterKind::blackman_harris);
    EXPECT_FLOAT_EQ(b.settings.filter.width, 2.0f);
    // Mitchell's default width is its cubic's natural support, 4 pixels (pbrt-v4's radius 2).
    const SceneDescription m = parse_scene_json(with_render([](Json& r) { r["filter"] = "mitchell"; }), kSource);
    EXPECT_EQ(m.settings.filter.kind, FilterKind::mitchell);
    EXPECT_FLOAT_EQ(m.settings.filter.width, 4.0f);
    // A filter other than the unit box is an image setting a checkpoint stores and must match,
    // and can be stored (a setting's value is one token).
    bool stored = false;
    for (const NamedSetting& s : image_settings(m.settings)) {
        if (s.name != "filter") continue;
        stored = true;
        EXPECT_EQ(s.value, "mitchell/4");
        EXPECT_EQ(s.value.find_first_of(" \t\n"), std::string::npos);
    }
    EXPECT_TRUE(stored);
    expect_scene_error(with_render([](Json& r) { r["filter"] = "lanczos"; }),
                       "render.filter: must be one of \"box\", \"gaussian\", \"blackman_harris\", \"mitchell\"");
    expect_scene_error(with_render([](Json& r) { r["filter_width"] = 0; }), "render.filter_width: must be greater than 0");
    expect_scene_error(with_render([](Json& r) { r["filter_width"] = -1; }), "render.filter_width: must be greater than 0");
    expect_scene_error(with_render([](Json& r) { r["filter_width"] = 17; }), "render.filter_width: must be greater than 0 and at most 16");
}

}  // namespace
}  // namespace wt
