#pragma once
// Ctrl-C and SIGTERM during a render. The first asks the render to stop at the next pass
// boundary, where the images (and a checkpoint, if asked for) are written and the program exits
// with `exit_interrupted`. The second exits at once: it removes only the temporary file being
// written at that moment (core/system/atomic_file.h), so every file already in place stays intact.

#include <atomic>

namespace wt {

constexpr int exit_interrupted = 3;  // stopped by a signal, after writing what it had

void install_interrupt_handlers();
// Set by the first SIGINT or SIGTERM after install_interrupt_handlers().
const std::atomic<bool>& interrupt_requested();

}  // namespace wt
