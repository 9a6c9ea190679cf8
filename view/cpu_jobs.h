// What the viewer asks of the CPU reference in the background, while the window keeps
// rendering: the live compare (the same view rendered on the CPU, then `compare` against the
// window's accumulation) and the click-to-pathdiff (path logs of one pixel and sample from both
// engines, then `pathdiff`). Each runs on its own thread; the frame loop polls for the outcome.
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"
#include "verify/plan.h"
#include "view/window_engine.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

#include <atomic>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace tp {

struct CpuJobOutcome {
    std::vector<std::string> lines;   // for the overlay and stdout
    std::vector<uint8_t> picture_rgb; // live compare: the significance map (RGB8); else empty
};

class CpuJob {
  public:
    // `twinpath verify` of the window's view without its triage (verify/verify.h): the window's
    // accumulation (`window`, which the frame loop serves) against the CPU reference rendering
    // `scene` (the window's camera in its params) with the same sampler (SAMPLER_*) and seeds of
    // its own. verify plans the CPU's samples and how far the window accumulates, the two render
    // at once, and compare decides; writes nothing. Setting `stop` ends it (a camera move).
    static std::unique_ptr<CpuJob> live_compare(FlatScene scene,
                                                std::shared_ptr<WindowEngine> window, uint32_t seed,
                                                uint32_t sampler, uint32_t threads,
                                                PlanRequest plan, std::atomic<bool>* stop);
    // Renders pixel (x, y) sample 0 with path logs on both engines (the GPU through
    // render_vulkan on `vk`, a device of its own), writes them to `log_prefix`_gpu.json and
    // _cpu.json and runs pathdiff on them.
    static std::unique_ptr<CpuJob> pathdiff(FlatScene scene, uint32_t x, uint32_t y, uint32_t seed,
                                            uint32_t sampler, uint32_t threads, VulkanOptions vk,
                                            std::string scene_path, std::string log_prefix);

    // What the job is doing, for the overlay while it runs ("CPU reference: pilots 40%").
    std::string activity() const;
    // The outcome once the job has finished (errors become its lines), else nothing.
    std::optional<CpuJobOutcome> poll();

  private:
    mutable std::mutex activity_mutex_;
    std::string activity_;
    std::future<CpuJobOutcome> result_;
};

} // namespace tp
