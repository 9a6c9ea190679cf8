#include "bench/renderer_version.h"

#include "bench/renderer_hash.h"

#include <fmt/format.h>

namespace tp::bench {

std::string renderer_version() {
    return fmt::format("{}+{}", TWINPATH_VERSION, TWINPATH_RENDERER_HASH);
}

} // namespace tp::bench
