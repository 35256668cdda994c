#pragma once
// Text output (CSV tables) that is either complete or absent: written beside the target and
// renamed over it, as images are (core/film/image_output.h).

#include <string>

namespace wt {

// Throws std::runtime_error naming the path if its directory does not exist or is not writable;
// called before the work that produces the text, so a typo costs nothing.
void check_text_output_path(const std::string& path);

void write_text_file_atomically(const std::string& path, const std::string& text);

}  // namespace wt
