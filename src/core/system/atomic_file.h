#pragma once
// Writing a file so that the name only ever holds a complete file: the content goes to a
// temporary file beside the target, which is flushed to the disk (fsync) and renamed over the
// target, and the directory is synced so the rename survives a crash. A failure at any step
// (disk full, unwritable directory, a killed process) leaves the previous file as it was.
//
// The temporary's name is registered while it exists, so an emergency exit (a second Ctrl-C:
// tools/render/interrupt.h) can remove it with async-signal-safe calls only.

#include <functional>
#include <stdexcept>
#include <string>

namespace wt {

struct FileWriteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Calls write(temporary_path) to create the content, then syncs and renames. `write` may open
// the path itself (OpenImageIO does) and must throw on failure; the temporary keeps the
// target's extension, since OpenImageIO picks its writer from it. Throws FileWriteError
// naming `path` (or rethrows what `write` threw), with the temporary removed.
void write_file_atomically(const std::string& path, const std::function<void(const std::string& temporary)>& write);

// The same for a text (a CSV table).
void write_text_file_atomically(const std::string& path, const std::string& text);

// Checked before the work whose result goes to `path`, so a typo costs nothing: its directory
// exists and is writable. Throws FileWriteError naming the path.
void check_output_directory(const std::string& path);

// The temporary file being written right now, or an empty string: for a signal handler.
const char* temporary_file_in_progress();

}  // namespace wt
