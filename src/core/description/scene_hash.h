#pragma once
// A fingerprint of what a scene renders, so a checkpoint, a partial render or an image can be
// matched to the scene it came from: camera, materials and every vertex, index, normal and
// sphere, bit for bit. Render settings are not in it (resolution, spp, seed ... are compared
// one by one, so a mismatch can be named); neither is the file's formatting, or its path.

#include <cstdint>
#include <string>

#include "core/description/scene_description.h"

namespace wt {

uint64_t scene_content_hash(const SceneDescription& description);

// 16 lowercase hex digits.
std::string hash_to_hex(uint64_t hash);

}  // namespace wt
