// One engine as `twinpath verify` drives it (docs/debugging.md, "verify"): something that
// renders the scene's image with a given number of samples and seed, and, for the triage, its
// AOVs and one pixel's path log. The CPU reference and a Vulkan mode are engines
// (render_engines.h); so is the viewer's window, whose accumulation is its image (view/).
#pragma once

#include "image/exr_io.h"
#include "render/render_options.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tp {

// One render verify asks for.
struct EngineRequest {
    uint32_t spp = 0;
    uint32_t seed = 0;
    DebugRequest debug; // AOVs or a path log (triage)
    // Set by verify when another engine failed or the caller gave up: end after the pass in
    // flight (RenderOptions::stop).
    const std::atomic<bool>* stop = nullptr;
    std::function<void(double fraction)> progress; // may be empty
};

// What it returns.
struct EngineRun {
    RenderResult result;
    ExrImage image;          // the EXR `twinpath render` writes for it (render_exr)
    double setup_s = 0;      // from the request to the first sample
    double sampling_s = 0;   // from the first sample to the end
    uint32_t kept_spp = 0;   // samples of a pilot that the engine's image will keep (the window)
    std::string device;      // the device it ran on, for the report
    nlohmann::json path_log; // with request.debug.log: the path log `render --debug-log` writes
    // The `twinpath render` arguments that make the same image (without -o), and the
    // environment they need (TWINPATH_DEBUG_SPIRV), for the report's commands.sh; empty where
    // no command line reproduces it (the window).
    std::vector<std::string> command, environment;
};

class Engine {
  public:
    virtual ~Engine() = default;
    // "cpu", "vulkan compute", "window": names in every line verify prints and in file names.
    virtual std::string label() const = 0;
    // Engines of one lane share a device and render one after another; lanes render at once.
    virtual int lane() const = 0;
    // A render of request.spp samples with request.seed.
    virtual EngineRun render(const EngineRequest& request) = 0;
    // The short render that measures the noise and the cost per sample (verify.h). An engine that
    // accumulates anyway (the window) returns what it has, sets kept_spp and keeps it for its
    // image.
    virtual EngineRun pilot(const EngineRequest& request) { return render(request); }
    // The seed this engine's pilot and image have whatever verify asks (the window's own), or
    // none: verify chooses.
    virtual std::optional<uint32_t> own_seed() const { return std::nullopt; }
};

} // namespace tp
