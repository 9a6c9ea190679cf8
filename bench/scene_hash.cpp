#include "bench/scene_hash.h"

#include "bench/renderer_version.h"

#include <fmt/format.h>

namespace tp::bench {

uint64_t hash_flat_scene(const FlatScene& s) {
    Fnv1a h;
    h.value(s.params);
    h.value(s.spp);
    add_scene_content(h, s);
    return h.get();
}

std::string renderer_version() {
    return fmt::format("{}+{}", TWINPATH_VERSION, TWINPATH_RENDERER_HASH);
}

} // namespace tp::bench
