#pragma once
// Reads a JSON scene file (format: docs/scene-format.md) into a SceneDescription, rejecting
// anything the renderer would silently mis-render: unknown keys, out-of-range values,
// dangling material names, degenerate lights. build_scene() trusts what comes out of here.

#include <stdexcept>
#include <string>

#include "core/scene_description.h"

namespace wt {

// what() is the complete message for the user: "SOURCE: FIELD.PATH: problem, got VALUE",
// or "SOURCE:LINE:COLUMN: JSON syntax error: ..." when the text is not JSON at all.
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws SceneError if the file cannot be read or is not a valid scene.
SceneDescription load_scene_file(const std::string& path);

// source_name only labels error messages (a path, or e.g. "test" in unit tests).
SceneDescription parse_scene_json(const std::string& text, const std::string& source_name);

}  // namespace wt
