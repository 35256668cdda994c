// libFuzzer target, compiled once per mesh format (WT_FUZZ_EXTENSION: ".obj", ".ply", ".glb"):
// a mesh file and the files beside it (fuzz_files.h: MTL files, .bin buffers, texture images)
// written into a directory of the process's own, then loaded as `wavetrace render` loads a
// scene naming it: a mesh_file shape with the file's own materials ("material": "from_file",
// which reads their textures and takes a glTF's lights) through parse_scene_json; and for glTF
// also the file's first camera ("camera": {"gltf": ...}). Anything but a SceneError is a finding.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/scene_file/scene_loader.h"
#include "fuzz_files.h"

#ifndef WT_FUZZ_EXTENSION
#error "define WT_FUZZ_EXTENSION as the mesh file extension, e.g. \".ply\""
#endif

namespace {

const std::string kMeshName = std::string("mesh") + WT_FUZZ_EXTENSION;

const std::string kMeshScene = R"({
  "camera": {"eye": [0, -5, 0], "look_at": [0, 0, 0]},
  "materials": {},
  "shapes": [{"type": "mesh_file", "file": ")" + kMeshName + R"(", "material": "from_file"}]
})";

const std::string kCameraScene = R"({
  "camera": {"gltf": ")" + kMeshName + R"(", "index": 0},
  "materials": {"white": {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "white"}]
})";

// WT_FUZZ_SHOW_REFUSALS=1 prints why the loader refused an input: to check that a seed gets as
// far as it was written to (`fuzz_obj seed` runs one input).
void load(const std::string& scene, const std::string& directory) {
    static const bool show = std::getenv("WT_FUZZ_SHOW_REFUSALS") != nullptr;
    try {
        wt::parse_scene_json(scene, directory + "/scene.json");
    } catch (const wt::SceneError& e) {
        if (show) std::fprintf(stderr, "refused: %s\n", e.what());
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    static wt::fuzz::FuzzDirectory directory;
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    if (!directory.hold(wt::fuzz::split_fuzz_files(input, kMeshName))) return 0;
    load(kMeshScene, directory.path());
    if (std::string_view(WT_FUZZ_EXTENSION) == ".glb") load(kCameraScene, directory.path());
    return 0;
}
