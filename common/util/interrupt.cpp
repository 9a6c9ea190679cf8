#include "util/interrupt.h"

#include <csignal>
#include <cstddef>
#include <unistd.h>

namespace tp {
namespace {

// Lock-free atomics only: the handler may touch nothing else (async-signal safety).
std::atomic<bool> g_saving{false}; // save_on_interrupt() was called: the render has begun
std::atomic<bool> g_stop{false};
std::atomic<int> g_first{0};   // the first signal's number
std::atomic<int> g_pending{0}; // a second signal's number, while an output is being written
std::atomic<int> g_writing{0}; // open OutputWriteScopes

// write() is async-signal safe; fmt and stdio are not.
template <size_t N>
void note(const char (&text)[N]) {
    (void)!::write(STDERR_FILENO, text, N - 1);
}

void on_signal(int sig) {
    int none = 0;
    if (g_first.compare_exchange_strong(none, sig)) {
        if (!g_saving.load()) {
            note("twinpath: interrupted before rendering began: nothing to save\n");
            _exit(128 + sig);
        }
        // The note first: whoever waits for it (a user, a script) sees it before anything the
        // stop leads to, the outputs and the final "wrote the N of M spp".
        note("\ntwinpath: interrupted: finishing the pass in flight to save it (a second signal "
             "exits at once)\n");
        g_stop.store(true);
        return;
    }
    if (g_writing.load() > 0) {
        g_pending.store(sig);
        return;
    }
    _exit(128 + sig);
}

} // namespace

void install_interrupt_handlers() {
    static const bool installed = [] {
        struct sigaction sa {};
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESTART; // file writes and waits go on; the render polls the flag
        sigaction(SIGINT, &sa, nullptr);
        sigaction(SIGTERM, &sa, nullptr);
        return true;
    }();
    (void)installed;
}

void save_on_interrupt() {
    g_saving.store(true);
}

const std::atomic<bool>& interrupt_flag() {
    return g_stop;
}

int interrupt_exit_code() {
    const int sig = g_first.load();
    return sig ? 128 + sig : 0;
}

OutputWriteScope::OutputWriteScope() {
    g_writing.fetch_add(1);
}

OutputWriteScope::~OutputWriteScope() {
    if (g_writing.fetch_sub(1) == 1 && g_pending.load() != 0) _exit(128 + g_pending.load());
}

} // namespace tp
