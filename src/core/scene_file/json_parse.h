#pragma once
// Scene-file text to JSON, with the positions and paths a user needs when the text is wrong.

#include <string>

#include "core/scene_file/json_reader.h"

namespace wt {

// Throws SceneError "SOURCE:LINE:COLUMN: JSON syntax error: ...", or names the JSON path of a
// repeated key or of a number literal too large for a double.
Json parse_json(const std::string& text, const std::string& source);

}  // namespace wt
