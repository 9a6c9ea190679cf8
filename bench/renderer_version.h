// The version of the renderer that made an image: the project version and the hash of the
// sources that decide what the CPU reference renders (bench/renderer_version.cmake). It keys
// the reference cache together with the render inputs (scene/scene_hash.h), and every bench
// result records it.
#pragma once

#include <string>

namespace tp::bench {

// "0.1.0+<16 hex digits>".
std::string renderer_version();

} // namespace tp::bench
