#pragma once
// Reads a JSON scene file (format: README.md, "Scene file format") into a SceneDescription, rejecting
// anything the renderer would silently mis-render: unknown keys, out-of-range values,
// dangling material names, degenerate lights. build_scene() trusts what comes out of here.

#include <string>

#include "core/description/scene_description.h"
#include "core/scene_file/scene_error.h"

namespace wt {

// Throws SceneError if the file cannot be read or is not a valid scene.
SceneDescription load_scene_file(const std::string& path);

// source_name labels error messages (a path, or e.g. "test" in unit tests); mesh files are
// found relative to its directory.
SceneDescription parse_scene_json(const std::string& text, const std::string& source_name);

}  // namespace wt
