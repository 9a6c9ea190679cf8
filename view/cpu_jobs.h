// What the viewer asks of the CPU reference in the background, while the window keeps
// rendering: the live compare (the same view rendered on the CPU, then `compare` against the
// window's accumulation) and the click-to-pathdiff (path logs of one pixel and sample from both
// engines, then `pathdiff`). Each runs on its own thread; the frame loop polls for the outcome.
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

#include <atomic>
#include <future>
#include <memory>
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
    // Renders `scene` (the window's camera in its params) on the CPU with as many samples as
    // `gpu` has and the same sampler (SAMPLER_*), with a different seed so that the two
    // estimates are independent (the two-sample test's assumption, docs/compare.md), compares,
    // and writes nothing.
    static std::unique_ptr<CpuJob> live_compare(FlatScene scene, RenderResult gpu, uint32_t seed,
                                                uint32_t sampler, uint32_t threads);
    // Renders pixel (x, y) sample 0 with path logs on both engines (the GPU through
    // render_vulkan on `vk`, a device of its own), writes them to `log_prefix`_gpu.json and
    // _cpu.json and runs pathdiff on them.
    static std::unique_ptr<CpuJob> pathdiff(FlatScene scene, uint32_t x, uint32_t y, uint32_t seed,
                                            uint32_t sampler, uint32_t threads, VulkanOptions vk,
                                            std::string scene_path, std::string log_prefix);

    double progress() const { return progress_.load(); }
    // The outcome once the job has finished (errors become its lines), else nothing.
    std::optional<CpuJobOutcome> poll();

  private:
    std::atomic<double> progress_{0.0};
    std::future<CpuJobOutcome> result_;
};

} // namespace tp
