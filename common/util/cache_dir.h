// twinpath's cache directory, one rule for every cache (docs/bench.md, "The cache directory"):
// the pipeline cache (pipelines/), and the benchmark's references, generated scenes and peer
// renders. It is $TWINPATH_CACHE, else $XDG_CACHE_HOME/twinpath, else $HOME/.cache/twinpath; a
// variable that is set but empty counts as unset, as the XDG base directory specification has
// it for XDG_CACHE_HOME. With none of the three there is no cache directory: a cache that is an
// optimization (the pipeline cache) is off, and a command that needs one (bench) asks for it.
#pragma once

#include <string>

namespace tp {

// The directory by the rule above, or "" when there is none.
std::string cache_dir();

} // namespace tp
