// twinpath view: the interactive progressive window (docs/view.md). The Vulkan engine
// accumulates frame by frame into the film `render` uses, shown tone-mapped as --png shows it;
// the camera moves with the mouse and keys and every move starts the accumulation again; the
// CPU reference renders the same view on request (live compare) and replays a clicked pixel's
// paths (click-to-pathdiff). Headless, the same frame loop runs without a window and reports
// its frame times.
#pragma once

#include "scene/flatten.h"
#include "verify/plan.h"
#include "vulkan_rt/device/vk_mode.h"
#include "vulkan_rt/present/progressive_renderer.h"

#include <cstdint>
#include <string>

namespace tp {

struct ViewOptions {
    std::string scene_path;         // in P's command line and the saved files' names
    std::string device;             // --device
    VkModeRequest vk_mode;          // --vk-mode; none: auto
    ProgressiveOptions progressive; // seed, --spp (max_spp), --spp-per-frame
    uint32_t frames = 0;            // --frames: stop after this many; 0: when the window closes
    std::string screenshot;         // --screenshot: the last frame's window content as PNG
    std::string script;             // --script: timed actions (view_input.h)
    bool headless = false;          // --headless: no window, frame times on stdout
    std::string exposure = "0";     // --exposure STOPS|auto of the display
    uint32_t threads = 0;           // CPU threads of the live compare and the path replay
    PlanRequest verify;             // C: --detect and --time-budget (verify/plan.h)
};

// Returns the exit code; throws InputError (2) and RuntimeError (3, also for no display).
int run_view(const FlatScene& scene, const ViewOptions& options);

} // namespace tp
