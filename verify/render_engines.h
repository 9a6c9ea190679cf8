// The engines of `twinpath verify`: the CPU reference (lane 0: its threads) and the Vulkan modes
// (lane 1: one device, its modes one after another). Each renders exactly what `twinpath render`
// renders with the same flags, and says which flags those are (EngineRun::command), so that the
// report's commands reproduce every image bit for bit (docs/design.md, "Accumulation order").
#pragma once

#include "scene/flatten.h"
#include "verify/engine.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

#include <memory>
#include <string>
#include <vector>

namespace tp {

// What every engine of one verification shares.
struct EngineSetup {
    const FlatScene* scene = nullptr; // each engine keeps a copy (its spp changes per render)
    std::string scene_path;           // the loaded file, for path logs and headers
    // The `render` arguments that give this scene, camera and film (the scene's name or file,
    // --width, --eye, --max-depth, --sampler ...), for the commands.
    std::vector<std::string> scene_args;
    uint32_t sampler = SAMPLER_SOBOL; // SAMPLER_*, the default of render (docs/sampling.md)
    uint32_t threads = 0;             // CPU threads; 0: all
};

class CpuEngine : public Engine {
  public:
    explicit CpuEngine(EngineSetup setup) : setup_(std::move(setup)), scene_(*setup_.scene) {}
    std::string label() const override { return "cpu"; }
    int lane() const override { return 0; }
    EngineRun render(const EngineRequest& request) override;

  private:
    EngineSetup setup_;
    FlatScene scene_;
};

class VulkanEngine : public Engine {
  public:
    // `vk.mode` must be a mode, not auto (vulkan_engine_modes resolves it).
    VulkanEngine(EngineSetup setup, VulkanOptions vk)
        : setup_(std::move(setup)), scene_(*setup_.scene), vk_(std::move(vk)) {}
    std::string label() const override;
    int lane() const override { return 1; }
    EngineRun render(const EngineRequest& request) override;

  private:
    EngineSetup setup_;
    FlatScene scene_;
    VulkanOptions vk_;
};

// The modes that --vk-mode WORD checks on the devices `device` selects: auto resolves as
// `render` resolves it there, "both" is compute and pipeline. Throws InputError for another
// word and RuntimeError (exit 3) when a device lacks a mode asked for, before anything renders.
std::vector<VkMode> vulkan_engine_modes(const std::string& word, const std::string& device);

// The CPU reference, then one engine per mode.
std::vector<std::unique_ptr<Engine>>
make_engines(const EngineSetup& setup, const std::vector<VkMode>& modes, const VulkanOptions& vk);

} // namespace tp
