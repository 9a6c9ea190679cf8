// SIGINT and SIGTERM during a render (docs/design.md, exit codes 130 and 143; README, "Interrupting
// a render"). Until the first pass begins (save_on_interrupt), a signal exits at once with 128 +
// its number: nothing has been rendered, so nothing is lost. From then on, the first signal asks
// the render to stop after the pass in flight, so that what was accumulated is written as a valid
// image; a second signal exits at once. An output being written at that moment is finished first
// (OutputWriteScope), so no PATH.partial is ever left behind.
#pragma once

#include <atomic>

namespace tp {

// Installs the handlers for SIGINT and SIGTERM (once; later calls do nothing). Called before any
// work that takes time, so that no signal finds the default action (death without a word).
void install_interrupt_handlers();

// From now on the first signal sets interrupt_flag() instead of exiting: the render has begun
// and its passes are worth saving.
void save_on_interrupt();

// Set by the first signal after save_on_interrupt(); a renderer polls it between passes
// (RenderOptions::stop).
const std::atomic<bool>& interrupt_flag();

// 128 + the first signal's number (130 for SIGINT, 143 for SIGTERM), or 0 when none came.
int interrupt_exit_code();

// Held while an output file is written (util/output_file.h): a second signal that arrives
// meanwhile exits when the last scope closes, after the file is whole or removed.
class OutputWriteScope {
  public:
    OutputWriteScope();
    ~OutputWriteScope();
    OutputWriteScope(const OutputWriteScope&) = delete;
    OutputWriteScope& operator=(const OutputWriteScope&) = delete;
};

} // namespace tp
