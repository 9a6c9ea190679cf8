// The two kinds of failure the command line reports (docs/design.md, exit codes):
// InputError -> exit 2 (bad usage or bad input), RuntimeError -> exit 3 (no device, out of
// memory, device lost). Messages name the file and the line or field where they can.
#pragma once

#include <fmt/format.h>
#include <stdexcept>
#include <string>

namespace tp {

struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct RuntimeError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

template <typename... Args>
[[noreturn]] void input_error(fmt::format_string<Args...> f, Args&&... args) {
    throw InputError(fmt::format(f, std::forward<Args>(args)...));
}

template <typename... Args>
[[noreturn]] void runtime_error(fmt::format_string<Args...> f, Args&&... args) {
    throw RuntimeError(fmt::format(f, std::forward<Args>(args)...));
}

} // namespace tp
