// libFuzzer target: a scene file's text through the loader (parse_scene_json) and, when it is
// valid, build_scene, as `wavetrace render` does. Anything but a SceneError is a finding.

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/scene/scene.h"
#include "core/scene_file/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        // Mesh files are looked up beside "fuzz/scene.json": a directory that does not exist,
        // so a scene cannot name the machine's files by relative path.
        const wt::SceneDescription description = wt::parse_scene_json(text, "/nonexistent-fuzz-dir/scene.json");
        const wt::Scene scene = wt::build_scene(description);
        (void)scene;
    } catch (const wt::SceneError&) {
    }
    return 0;
}
