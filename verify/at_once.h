// Renders on several engines at once (docs/debugging.md, "verify"): one thread per lane, the
// engines of a lane one after another (they share a device), every lane at the same time (the
// CPU's threads and the GPU). Progress goes to one callback, the whole's one line.
#pragma once

#include "verify/engine.h"

#include <atomic>
#include <functional>
#include <vector>

namespace tp {

// Engine k's progress: the fraction of its render done.
using AtOnceProgress = std::function<void(size_t engine, double fraction)>;

// Runs `render(engine k, request k)` for every k, lanes at once. `stop` ends every render after
// its pass in flight when set; a render that throws sets it, and the first exception is rethrown
// once every lane has ended. `progress` may be called from any lane's thread (serialised here).
std::vector<EngineRun>
render_at_once(const std::vector<Engine*>& engines, std::vector<EngineRequest> requests,
               const std::function<EngineRun(Engine&, const EngineRequest&)>& render,
               std::atomic<bool>& stop, const AtOnceProgress& progress);

} // namespace tp
