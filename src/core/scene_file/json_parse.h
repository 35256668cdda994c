#pragma once
// Scene-file text to JSON, with the positions and paths a user needs when the text is wrong.

#include <cstddef>
#include <string>

#include "core/scene_file/json_reader.h"

namespace wt {

// Deeper nesting is refused while parsing: printing a value recurses once per level.
constexpr std::size_t kMaxJsonDepth = 64;

// Throws SceneError "SOURCE:LINE:COLUMN: JSON syntax error: ...", or names the JSON path of a
// repeated key, of a number literal too large for a double, or of nesting deeper than
// kMaxJsonDepth. Time and memory are linear in the text's size.
Json parse_json(const std::string& text, const std::string& source);

}  // namespace wt
