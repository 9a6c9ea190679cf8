#include "util/interrupt.h"

#include <csignal>
#include <unistd.h>

namespace tp {
namespace {

// Lock-free atomics only: the handler may touch nothing else (async-signal safety).
std::atomic<bool> g_stop{false};
std::atomic<int> g_first{0};   // the first signal's number
std::atomic<int> g_pending{0}; // a second signal's number, while an output is being written
std::atomic<int> g_writing{0}; // open OutputWriteScopes

void on_signal(int sig) {
    int none = 0;
    if (g_first.compare_exchange_strong(none, sig)) {
        g_stop.store(true);
        static const char kNote[] = "\ntwinpath: interrupted: finishing the pass in flight to save "
                                    "it (a second signal exits at once)\n";
        (void)!::write(STDERR_FILENO, kNote, sizeof kNote - 1); // write() is async-signal safe
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
