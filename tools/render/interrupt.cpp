#include "tools/render/interrupt.h"

#include <signal.h>
#include <unistd.h>

#include <cstring>

#include "core/system/atomic_file.h"

namespace wt {

namespace {

std::atomic<bool> requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "read and written from a signal handler");

void say(const char* text) {
    // write(2), not iostreams: nothing but async-signal-safe calls in a handler.
    [[maybe_unused]] const ssize_t n = write(STDERR_FILENO, text, std::strlen(text));
}

void on_signal(int signal) {
    if (!requested.exchange(true)) {
        say("\nwavetrace: interrupted: finishing this pass, then writing what it has (again to quit at once)\n");
        return;
    }
    const char* temporary = temporary_file_in_progress();
    if (temporary[0] != '\0') unlink(temporary);
    say("\nwavetrace: interrupted twice: quitting without writing\n");
    _exit(128 + signal);
}

}  // namespace

void install_interrupt_handlers() {
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // a signal in the middle of a write does not fail the write
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

const std::atomic<bool>& interrupt_requested() { return requested; }

}  // namespace wt
