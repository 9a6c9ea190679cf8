// A scope whose allocations, made by the calling thread, LeakSanitizer leaves out of its check at
// exit (the `debug` preset builds with AddressSanitizer, which includes it). For what a library
// allocates once and keeps for the life of the process, which is not ours to free. Without
// AddressSanitizer it does nothing.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

namespace tp {

class LeakCheckPause {
  public:
#if defined(__SANITIZE_ADDRESS__)
    LeakCheckPause() {
        __lsan_disable();
    }
    ~LeakCheckPause() {
        __lsan_enable();
    }
#else
    LeakCheckPause() {} // user-provided: a scope object of this type is not "unused"
#endif
    LeakCheckPause(const LeakCheckPause&) = delete;
    LeakCheckPause& operator=(const LeakCheckPause&) = delete;
};

} // namespace tp
