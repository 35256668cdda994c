// glTF cameras through the scene loader ("camera": {"gltf": FILE, "name" or "index"}): placed by
// their node's world transform under a hierarchy of translations, rotations and scales, worked
// out by hand; perspective yfov and orthographic xmag; the scene's transform after the file's;
// the render the same bits as the camera written out; every bad file, name, index, placement
// and projection refused naming the scene file, the field and the glTF file.

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "import_gltf_files.h"
#include "render_helpers.h"

namespace {

using wt::CameraDescription;
using wt::Projection;
using wt::SceneDescription;
using wt::parse_scene_json;
using Json = nlohmann::json;

using GltfCameras = wt::test::ImportTest;

constexpr double kPi = 3.14159265358979323846;
const double kHalfSqrt2 = std::sqrt(0.5);

// A glTF of nodes and cameras only: a camera needs no mesh. (A braced list of one object is that
// object to nlohmann::json, not an array of it: one node or camera is wrapped here.)
std::string gltf(const Json& nodes, const Json& cameras, const Json& roots = Json::array({0})) {
    const auto list = [](const Json& j) { return j.is_array() ? j : Json::array({j}); };
    return Json{{"asset", {{"version", "2.0"}}}, {"scenes", Json::array({{{"nodes", roots}}})}, {"nodes", list(nodes)},
                {"cameras", list(cameras)}}
        .dump();
}

Json perspective(const std::string& name, double yfov, double aspect = 0.0) {
    Json p = {{"yfov", yfov}, {"znear", 0.1}};
    if (aspect > 0.0) p["aspectRatio"] = aspect;
    return {{"type", "perspective"}, {"name", name}, {"perspective", p}};
}

Json orthographic(const std::string& name, double xmag, double ymag) {
    return {{"type", "orthographic"},
            {"name", name},
            {"orthographic", {{"xmag", xmag}, {"ymag", ymag}, {"znear", 0.1}, {"zfar", 100.0}}}};
}

// Root node 0: translate (1, 2, 3), turn 90 degrees about z, scale 2; its children:
//   node 1 at (0, 0, 1), turned 90 degrees about x, holding camera 0 (perspective, "Persp");
//   node 2 at (0, 0, -1), turned 180 degrees about y, holding camera 1 (orthographic, "Ortho").
// By hand, camera 0: R_x(90) takes the local view -z to +y and up +y to +z; R_z(90) then takes
// +y to -x and keeps +z; the scale changes no direction. Its eye is (1, 2, 3) + R_z(90) (2 (0, 0,
// 1)) = (1, 2, 5). Camera 1: R_y(180) takes -z to +z and keeps +y; R_z(90) keeps +z and takes +y
// to -x; its eye is (1, 2, 3) + 2 (0, 0, -1) = (1, 2, 1).
std::string hierarchy_gltf() {
    const Json nodes = {
        {{"translation", {1, 2, 3}}, {"rotation", {0, 0, kHalfSqrt2, kHalfSqrt2}}, {"scale", {2, 2, 2}}, {"children", {1, 2}}},
        {{"name", "PerspNode"}, {"translation", {0, 0, 1}}, {"rotation", {kHalfSqrt2, 0, 0, kHalfSqrt2}}, {"camera", 0}},
        {{"name", "OrthoNode"}, {"translation", {0, 0, -1}}, {"rotation", {0, 1, 0, 0}}, {"camera", 1}}};
    return gltf(nodes, {perspective("Persp", 0.5, 1.5), orthographic("Ortho", 1.5, 1.0)});
}

void expect_vec3_near(const glm::vec3& v, glm::dvec3 expected, double tolerance = 1e-5) {
    EXPECT_NEAR(v.x, expected.x, tolerance);
    EXPECT_NEAR(v.y, expected.y, tolerance);
    EXPECT_NEAR(v.z, expected.z, tolerance);
}

// A scene with the given camera object and one lit quad.
std::string scene_with_camera(const std::string& camera, const std::string& render = R"({"width": 24, "height": 16, "spp": 4})") {
    return R"({"camera": )" + camera + R"(, "render": )" + render + R"(,
      "materials": {"white": {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]},
                    "lamp": {"type": "lambertian", "albedo": [0, 0, 0], "emission": [4, 4, 4]}},
      "shapes": [{"type": "quad", "vertices": [[3, -2, -2], [3, 2, -2], [3, 2, 2], [3, -2, 2]], "material": "white"},
                 {"type": "quad", "vertices": [[1, -0.5, 1.5], [1, 0.5, 1.5], [2, 0.5, 1.5], [2, -0.5, 1.5]], "material": "lamp"}]})";
}

TEST_F(GltfCameras, PerspectiveAndOrthographicArePlacedByTheirNodesHierarchy) {
    write("scene.gltf", hierarchy_gltf());
    const SceneDescription by_name = parse_scene_json(scene_with_camera(R"({"gltf": "scene.gltf", "name": "Persp"})"), path("scene.json"));
    const CameraDescription& p = by_name.camera;
    EXPECT_EQ(p.projection, Projection::perspective);
    expect_vec3_near(p.eye, {1, 2, 5});
    // |eye| = sqrt(30) = 5.5: look_at is the next power of two, 8, ahead.
    expect_vec3_near(p.look_at, {1 - 8, 2, 5});
    expect_vec3_near(p.up, {0, 0, 1});
    EXPECT_FLOAT_EQ(p.fov_degrees, float(0.5 * 180.0 / kPi));
    EXPECT_EQ(p.aperture_radius, 0.0f);
    // The file's aspect ratio (1.5) is the image's (24x16): no note.
    EXPECT_TRUE(by_name.notes.empty());

    const SceneDescription by_index = parse_scene_json(scene_with_camera(R"({"gltf": "scene.gltf", "index": 1})"), path("scene.json"));
    const CameraDescription& o = by_index.camera;
    EXPECT_EQ(o.projection, Projection::orthographic);
    expect_vec3_near(o.eye, {1, 2, 1});
    expect_vec3_near(o.look_at, {1, 2, 1 + 4});  // |eye| = sqrt(6): 4 ahead
    expect_vec3_near(o.up, {-1, 0, 0});
    EXPECT_EQ(o.width_world, 3.0f);  // twice xmag

    // The node's name picks the same camera as the camera's own.
    const SceneDescription by_node = parse_scene_json(scene_with_camera(R"({"gltf": "scene.gltf", "name": "OrthoNode"})"), path("scene.json"));
    EXPECT_EQ(by_node.camera.eye, o.eye);
    EXPECT_EQ(by_node.camera.look_at, o.look_at);
}

// The scene's transform comes after the file's, as for the file's meshes: a turn of 90 degrees
// about z and a shift by (10, 0, 0) take camera 0's eye (1, 2, 5) to (10 - 2, 1, 5) and its view
// -x to -y; the thin lens's keys work as for any perspective camera.
TEST_F(GltfCameras, TheScenesTransformAndTheThinLensApply) {
    write("scene.gltf", hierarchy_gltf());
    const SceneDescription d = parse_scene_json(
        scene_with_camera(R"({"gltf": "scene.gltf", "name": "Persp", "aperture_radius": 0.1, "focus_distance": 3,
                             "transform": {"rotate": {"axis": [0, 0, 1], "degrees": 90}, "translate": [10, 0, 0]}})"),
        path("scene.json"));
    expect_vec3_near(d.camera.eye, {8, 1, 5});
    const glm::vec3 forward = glm::normalize(d.camera.look_at - d.camera.eye);
    expect_vec3_near(forward, {0, -1, 0});
    expect_vec3_near(d.camera.up, {0, 0, 1});
    EXPECT_EQ(d.camera.aperture_radius, 0.1f);
    EXPECT_EQ(d.camera.focus_distance, 3.0f);
}

// A camera at (-1, 0, 0) looking along +x with +z up, given as an exact node matrix (columns: the
// local x to -y, y to +z, z to -x, the translation), and yfov pi/2: the same CameraDescription as
// the camera written out, so the same bits, on both integrators.
TEST_F(GltfCameras, RendersTheBitsOfTheSameCameraWrittenOut) {
    const Json nodes = {{{"matrix", {0, -1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0, 0, 1}}, {"camera", 0}}};
    write("exact.gltf", gltf(nodes, {perspective("Exact", kPi / 2)}));
    const SceneDescription from_gltf =
        parse_scene_json(scene_with_camera(R"({"gltf": "exact.gltf", "index": 0})"), path("scene.json"));
    const SceneDescription written =
        parse_scene_json(scene_with_camera(R"({"eye": [-1, 0, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov_degrees": 90})"),
                         path("scene.json"));
    EXPECT_EQ(from_gltf.camera.eye, written.camera.eye);
    EXPECT_EQ(from_gltf.camera.look_at, written.camera.look_at);
    EXPECT_EQ(from_gltf.camera.up, written.camera.up);
    EXPECT_EQ(from_gltf.camera.fov_degrees, written.camera.fov_degrees);
    // The image (24x16) is not the file's aspect ratio (none given): no note either.
    EXPECT_TRUE(from_gltf.notes.empty());
    const wt::Film expected = wt::test::render_film(written, wt::Integrator::wavefront, 2).film;
    double total = 0.0;
    for (uint32_t p = 0; p < expected.pixel_total(); ++p) total += expected.pixel_mean(p).x;
    EXPECT_GT(total, 0.0) << "the camera sees the lit wall";
    EXPECT_TRUE(wt::test::render_film(from_gltf, wt::Integrator::wavefront, 2).film == expected);
    EXPECT_TRUE(wt::test::render_film(from_gltf, wt::Integrator::reference, 2).film == expected);
}

// What the image decides and the file only hints at is a note, not an error.
TEST_F(GltfCameras, AnotherAspectRatioOrAMirroringNodeIsANote) {
    write("scene.gltf", hierarchy_gltf());
    const SceneDescription d = parse_scene_json(
        scene_with_camera(R"({"gltf": "scene.gltf", "name": "Persp"})", R"({"width": 16, "height": 16})"), path("scene.json"));
    ASSERT_EQ(d.notes.size(), 1u);
    EXPECT_NE(d.notes[0].find("scene.json: camera.name: "), std::string::npos) << d.notes[0];
    EXPECT_NE(d.notes[0].find("camera 0 (\"Persp\"): made for an aspect ratio of 1.5; the image's 16x16 (1) is used"),
              std::string::npos)
        << d.notes[0];
    const Json mirrored = {{{"scale", {-1, 1, 1}}, {"camera", 0}}};
    write("mirror.gltf", gltf(mirrored, {perspective("M", 1.0)}));
    const SceneDescription m = parse_scene_json(scene_with_camera(R"({"gltf": "mirror.gltf", "index": 0})"), path("scene.json"));
    ASSERT_EQ(m.notes.size(), 1u);
    EXPECT_NE(m.notes[0].find("mirrors; the image is not mirrored"), std::string::npos) << m.notes[0];
    expect_vec3_near(m.camera.look_at - m.camera.eye, {0, 0, -1});
}

class GltfCameraErrors : public wt::test::ImportTest {
protected:
    // The message for a scene whose camera is this JSON object; fails the test without one.
    std::string error_for_camera(const std::string& camera) const {
        try {
            parse_scene_json(scene_with_camera(camera), path("scene.json"));
        } catch (const wt::SceneError& e) {
            return e.what();
        }
        ADD_FAILURE() << "no SceneError for " << camera;
        return "";
    }
    void expect_error(const std::string& camera, const std::string& field, const std::string& problem) const {
        const std::string message = error_for_camera(camera);
        EXPECT_NE(message.find("scene.json: camera." + field + ": "), std::string::npos) << message;
        EXPECT_NE(message.find(".gltf"), std::string::npos) << message;
        EXPECT_NE(message.find(problem), std::string::npos) << message << "\nexpected to contain: " << problem;
    }
};

TEST_F(GltfCameraErrors, BadFilesNamesIndicesPlacementsAndProjectionsAreRefused) {
    write("scene.gltf", hierarchy_gltf());
    expect_error(R"({"gltf": "missing.gltf", "index": 0})", "gltf", "missing.gltf: cannot open");
    write("empty.gltf", gltf({Json::object()}, Json::array()));
    expect_error(R"({"gltf": "empty.gltf", "index": 0})", "gltf", "empty.gltf: the file has no cameras");
    write("broken.gltf", "{\"asset\": ");
    expect_error(R"({"gltf": "broken.gltf", "index": 0})", "gltf", "broken.gltf: ");
    expect_error(R"({"gltf": "scene.gltf", "name": "Front"})", "name",
                 "no camera (or node placing one) is named \"Front\" (cameras: \"Persp\", \"Ortho\")");
    expect_error(R"({"gltf": "scene.gltf", "index": 2})", "index", "camera index 2 is out of range (the file has 2 cameras)");

    // Camera 1 placed by no node; camera 0 by two.
    write("placing.gltf", gltf({{{"camera", 0}}, {{"camera", 0}}}, {perspective("Twice", 1.0), perspective("Never", 1.0)}, {0, 1}));
    expect_error(R"({"gltf": "placing.gltf", "name": "Never"})", "name",
                 "camera 1 (\"Never\"): no node of the file's scene places it");
    expect_error(R"({"gltf": "placing.gltf", "index": 0})", "index",
                 "camera 0 (\"Twice\"): placed 2 times (nodes 0, 1): which place is meant is ambiguous");
    // A node reached along two paths is two places too.
    write("shared.gltf", gltf({{{"children", {2}}}, {{"children", {2}}}, {{"camera", 0}}}, {perspective("Shared", 1.0)}, {0, 1}));
    expect_error(R"({"gltf": "shared.gltf", "index": 0})", "index", "its node reached through several parents");

    // Scale 0 anywhere above the camera leaves it no direction.
    write("flat.gltf", gltf({{{"scale", {1, 0, 1}}, {"children", {1}}}, {{"camera", 0}}}, {perspective("Flat", 1.0)}));
    expect_error(R"({"gltf": "flat.gltf", "index": 0})", "index", "node 1's world transform is degenerate");

    for (const std::string yfov : {"0", "-1", "4"}) {
        std::string text = gltf({{{"camera", 0}}}, {perspective("F", 12345.0)});
        text.replace(text.find("12345.0"), 7, yfov);
        write("fov.gltf", text);
        expect_error(R"({"gltf": "fov.gltf", "index": 0})", "index", "perspective.yfov must be greater than 0 and less than pi");
    }
    // JSON has no infinity, and the parser refuses a number that overflows to one.
    std::string infinite = gltf({{{"camera", 0}}}, {perspective("F", 12345.0)});
    infinite.replace(infinite.find("12345.0"), 7, "1e400");
    write("infinite.gltf", infinite);
    expect_error(R"({"gltf": "infinite.gltf", "index": 0})", "gltf", "number overflow parsing '1e400'");
    for (const double xmag : {0.0, -2.0}) {
        write("ortho.gltf", gltf({{{"camera", 0}}}, {orthographic("O", xmag, 1.0)}));
        expect_error(R"({"gltf": "ortho.gltf", "index": 0})", "index", "orthographic.xmag must be finite and greater than 0");
    }
    write("ortho.gltf", gltf({{{"camera", 0}}}, {orthographic("O", 1.0, 0.0)}));
    expect_error(R"({"gltf": "ortho.gltf", "index": 0})", "index", "orthographic.ymag must be finite and greater than 0");
}

TEST_F(GltfCameraErrors, TheSceneFileKeysAreChecked) {
    write("scene.gltf", hierarchy_gltf());
    const auto error = [&](const std::string& camera, const std::string& expected) {
        const std::string message = error_for_camera(camera);
        EXPECT_NE(message.find(expected), std::string::npos) << message << "\nexpected to contain: " << expected;
    };
    error(R"({"gltf": "scene.gltf"})", "camera: a glTF camera needs \"name\" or \"index\"");
    error(R"({"gltf": "scene.gltf", "name": "Persp", "index": 0})", "camera.index: cannot be given with name");
    error(R"({"gltf": "scene.gltf", "name": "Persp", "eye": [0, 0, 0]})", "camera.eye: comes from the glTF camera");
    error(R"({"gltf": "scene.gltf", "name": "Persp", "fov_degrees": 40})", "camera.fov_degrees: comes from the glTF camera");
    error(R"({"gltf": "scene.gltf", "name": "Persp", "zoom": 2})", "camera.zoom: unknown key for a glTF camera");
    error(R"({"gltf": "scene.gltf", "index": -1})", "camera.index: ");
    error(R"({"gltf": "scene.gltf", "name": "Persp", "aperture_radius": 0.1})",
          "camera.aperture_radius: needs focus_distance or focus_on with a glTF camera");
    error(R"({"gltf": "scene.gltf", "name": "Ortho", "focus_distance": 2})", "camera.focus_distance: is for a perspective camera");
    error(R"({"gltf": "scene.gltf", "name": "Persp", "transform": {"scale": 0}})", "camera.transform.scale: must be non-zero");
    write("model.obj", "v 0 0 0\n");
    error(R"({"gltf": "model.obj", "index": 0})", "camera.gltf: ");
    error(R"({"gltf": "model.obj", "index": 0})", "not a glTF file");
}

}  // namespace
