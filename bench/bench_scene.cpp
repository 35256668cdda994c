#include "bench_scene.h"

#include <string>

#include "core/scene_loader.h"

namespace wt::bench {

SceneDescription hexroom_description(int width, int height, int spp) {
    // WT_SCENES_DIR is the source tree's scenes/ (bench/CMakeLists.txt), so the programs run
    // from any working directory.
    SceneDescription description = load_scene_file(std::string(WT_SCENES_DIR) + "/hexroom.json");
    description.settings.width = width;
    description.settings.height = height;
    description.settings.spp = spp;
    return description;
}

}  // namespace wt::bench
