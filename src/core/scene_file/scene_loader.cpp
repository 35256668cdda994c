#include "core/scene_file/scene_loader.h"

#include "core/system/regular_file.h"
#include "core/scene_file/json_parse.h"
#include "core/scene_file/scene_schema.h"

namespace wt {

SceneDescription parse_scene_json(const std::string& text, const std::string& source_name) {
    const Json root = parse_json(text, source_name);
    const Reader in(source_name);
    in.expect_object(root, "");
    in.check_keys(root, "", {"camera", "render", "materials", "meshes", "shapes", "lights"});

    SceneDescription scene;
    // Fixed order, whatever the file's: shapes need the materials, a glTF camera's notes the image size.
    const Json* render = in.optional(root, "render");
    if (render) scene.settings = read_render(in, *render, "render");
    scene.camera = read_camera(in, in.required(root, "camera", ""), "camera", scene.settings, scene.notes);
    // Light tracing joins light paths to the camera, which an orthographic camera (one ray
    // direction) cannot be joined to; left unsaid, its caustics are the camera paths' (scene.cpp).
    const Json* caustics = render ? in.optional(*render, "caustics") : nullptr;
    if (caustics && scene.camera.projection == Projection::orthographic && scene.settings.estimator.caustics != CausticPaths::path)
        in.fail("render.caustics", std::string("\"") + name_of(scene.settings.estimator.caustics) +
                                       "\" needs a perspective camera (light paths cannot be joined to an "
                                       "orthographic one); use \"path\"");
    scene.materials = read_materials(in, in.required(root, "materials", ""), "materials", scene.textures);
    read_shapes(in, in.required(root, "shapes", ""), "shapes", scene, in.optional(root, "meshes"));
    // The list's lights first, then those the mesh files placed (read with the shapes).
    if (const Json* lights = in.optional(root, "lights")) {
        std::vector<LightDescription> listed = read_lights(in, *lights, "lights");
        scene.lights.insert(scene.lights.begin(), listed.begin(), listed.end());
    }
    return scene;
}

SceneDescription load_scene_file(const std::string& path) {
    std::string text;
    try {
        text = read_regular_file(path, kMaxSceneFileBytes);
    } catch (const InputFileError& e) {
        throw SceneError(e.what());
    }
    return parse_scene_json(text, path);
}

}  // namespace wt
