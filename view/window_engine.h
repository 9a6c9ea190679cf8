// The window's accumulation as an engine of verify (verify/engine.h), for the C key: its pilot
// is what the window has accumulated so far (with its seed and its time per sample), and its
// image is the accumulation once it has the samples the plan asks for; the pilot's samples are
// kept. The frame loop owns the renderer, so a request waits until the loop serves it (serve(),
// once a frame, on the loop's thread); verify runs on a thread of its own (cpu_jobs.h).
#pragma once

#include "scene/flatten.h"
#include "verify/engine.h"
#include "vulkan_rt/present/progressive_renderer.h"

#include <condition_variable>
#include <future>
#include <mutex>
#include <optional>
#include <string>

namespace tp {

class WindowEngine : public Engine {
  public:
    // `scene`: the window's view (its camera), for the image's header; `seed`, `sampler`: the
    // accumulation's.
    WindowEngine(FlatScene scene, uint32_t seed, uint32_t sampler, std::string mode);
    std::string label() const override { return "window"; }
    int lane() const override { return 1; }
    std::optional<uint32_t> own_seed() const override { return seed_; }
    EngineRun pilot(const EngineRequest& request) override;  // what the window has now
    EngineRun render(const EngineRequest& request) override; // once it has request.spp

    // The frame loop, after each frame: answers the waiting request when the accumulation has
    // the samples it asks for, or will get no more (`accumulating` false: --spp or --frames
    // reached), or the request's stop is set; reports its progress otherwise.
    void serve(const ProgressiveRenderer& renderer, bool accumulating);
    // The view this engine belongs to is gone (the camera moved): the waiting request and every
    // later one fail with `why`.
    void abandon(const std::string& why);

  private:
    EngineRun wait(const EngineRequest& request, bool pilot);

    FlatScene scene_;
    uint32_t seed_, sampler_;
    std::string mode_;
    std::mutex mutex_;
    struct Pending {
        const EngineRequest* request = nullptr;
        bool pilot = false;
        std::promise<EngineRun> done;
    };
    std::optional<Pending> pending_;
    std::string abandoned_; // non-empty: why no request will be served
};

} // namespace tp
