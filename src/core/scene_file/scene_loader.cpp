#include "core/scene_file/scene_loader.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "core/scene_file/json_parse.h"
#include "core/scene_file/scene_schema.h"

namespace wt {

SceneDescription parse_scene_json(const std::string& text, const std::string& source_name) {
    const Json root = parse_json(text, source_name);
    const Reader in(source_name);
    in.expect_object(root, "");
    in.check_keys(root, "", {"camera", "render", "materials", "shapes"});

    SceneDescription scene;
    // Fixed order, whatever the file's: shapes need the materials.
    scene.camera = read_camera(in, in.required(root, "camera", ""), "camera");
    if (const Json* render = in.optional(root, "render")) scene.settings = read_render(in, *render, "render");
    scene.materials = read_materials(in, in.required(root, "materials", ""), "materials");
    read_shapes(in, in.required(root, "shapes", ""), "shapes", scene);
    return scene;
}

SceneDescription load_scene_file(const std::string& path) {
    // C stdio rather than ifstream: fopen reliably sets errno, which makes the message useful.
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) throw SceneError(path + ": cannot open: " + std::strerror(errno));
    std::string text;
    char buffer[1 << 16];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) text.append(buffer, n);
    if (std::ferror(file.get())) throw SceneError(path + ": cannot read: " + std::strerror(errno));
    return parse_scene_json(text, path);
}

}  // namespace wt
