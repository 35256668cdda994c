#pragma once
// The scene every benchmark measures: the reference hexroom (scenes/hexroom.json), so the
// numbers speak about the geometry the renderer is built for.

#include "core/scene_description.h"

namespace wt::bench {

// The hexroom as its file describes it, at the resolution and sample count a benchmark needs.
SceneDescription hexroom_description(int width, int height, int spp);

}  // namespace wt::bench
