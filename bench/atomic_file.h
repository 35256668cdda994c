#pragma once
// Files the benchmark tools write (meshes, scenes) appear whole or not at all: an interrupted
// run must not leave a half-written mesh that a later run, or the bench_data target, would take
// for a finished one.

#include <functional>
#include <ostream>
#include <string>

namespace wt::bench {

// Calls write(stream) on a temporary file beside `path`, then renames it over `path`. Throws
// std::runtime_error naming `path` if the file cannot be created, written or moved into place,
// and removes the temporary file on any failure (an exception from `write` included).
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace wt::bench
