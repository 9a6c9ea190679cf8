#include "view/viewer.h"

#include "image/exposure.h"
#include "image/png_io.h"
#include "render/render_header.h"
#include "render/sampler.h"
#include "scene/features.h"
#include "shaders/display_interface.h"
#include "util/clock.h"
#include "util/error.h"
#include "view/cpu_jobs.h"
#include "view/overlay.h"
#include "view/view_camera.h"
#include "view/view_input.h"
#include "view/window.h"
#include "view/window_engine.h"
#include "vulkan_rt/present/presenter.h"

#include <fmt/core.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <numeric>
#include <thread>

namespace tp {
namespace {

// Mouse and key steps: a drag of one window height turns the camera by 2 radians; a wheel
// notch dollies by 10% and, with the modifier, changes the field of view by 2 degrees; a fly
// key moves by 2% of the target distance per frame held.
constexpr double kOrbitPerPixel = 2.0;
constexpr double kDollyPerNotch = 0.9;
constexpr double kFovPerNotch = 2.0;
constexpr double kFlyStep = 0.02;
// [ and ] change the display's exposure by half a stop (a factor sqrt 2).
constexpr float kExposureStep = 0.5f;
// The live compare's two-sample test estimates each pixel's variance from its own samples (none
// from one sample) and is calibrated from 16 spp on (docs/compare.md).
constexpr uint32_t kMinCompareSpp = 16;

std::string stem(const std::string& path) {
    return std::filesystem::path(path).stem().string();
}

// The first of NAME_1, NAME_2, ... whose .exr and .png do not exist yet.
std::string free_name(const std::string& base) {
    for (int k = 1;; ++k) {
        const std::string name = fmt::format("{}_{}", base, k);
        if (!std::filesystem::exists(name + ".exr") && !std::filesystem::exists(name + ".png"))
            return name;
    }
}

// The frames' wall times and, per frame, the GPU seconds of its passes (trace, resolve,
// display); the rest of a frame's wall time is the host's: recording, submitting and waiting,
// the counters' read-back and, in a window, presentation.
struct FrameTimes {
    std::vector<double> seconds;
    BatchSplit gpu; // summed over the frames
    uint64_t rays = 0;

    void add(double wall, const BatchSplit& split, uint64_t frame_rays) {
        seconds.push_back(wall);
        gpu.trace += split.trace;
        gpu.resolve += split.resolve;
        gpu.after += split.after;
        rays += frame_rays;
    }

    // `pass_fraction`: the rows that have one more sample than `spp` (frames in bands).
    std::string report(uint32_t spp, double pass_fraction) const {
        if (seconds.empty()) return "no frames";
        std::vector<double> s = seconds;
        std::sort(s.begin(), s.end());
        const double total = std::accumulate(s.begin(), s.end(), 0.0);
        const double n = double(s.size());
        const double mean = total / n;
        std::string text = fmt::format(
            "{} frames: mean {:.3f} ms, median {:.3f} ms, p95 {:.3f} ms, {:.1f} frames/s; {} spp; "
            "{:.1f} Mrays/s",
            s.size(), 1e3 * mean, 1e3 * s[s.size() / 2],
            1e3 * s[std::min(s.size() - 1, s.size() * 95 / 100)], 1.0 / mean, spp,
            total > 0 ? double(rays) / total * 1e-6 : 0.0);
        if (pass_fraction > 0)
            text += fmt::format("; frames are bands of rows: {:.0f}% of the image has {} spp",
                                100.0 * pass_fraction, spp + 1);
        const double gpu_total = gpu.trace + gpu.resolve + gpu.after;
        if (gpu_total > 0)
            text += fmt::format("; per frame: trace {:.3f} ms, resolve {:.3f} ms, display {:.3f} "
                                "ms (GPU), host {:.3f} ms",
                                1e3 * gpu.trace / n, 1e3 * gpu.resolve / n, 1e3 * gpu.after / n,
                                1e3 * (total - gpu_total) / n);
        return text;
    }
};

// The frame loop and everything the actions change; with a window or without (headless).
class Viewer {
  public:
    // `bgra`: the byte order of the window's pixels (Presenter::bgra).
    Viewer(const FlatScene& scene, const ViewOptions& o, const VulkanContext& ctx, bool bgra)
        : scene_(scene), o_(o), ctx_(ctx), bgra_(bgra), renderer_(ctx, scene, o.progressive),
          camera_(scene), width_(scene.params.camera.width), height_(scene.params.camera.height) {
        if (!o.script.empty()) script_ = read_view_script(o.script);
        text_.device = ctx.info().name;
        text_.mode = vk_mode_name(renderer_.mode());
        text_.scene = o.scene_path;
        const std::vector<std::string> features = analyze_features(scene).names();
        for (const std::string& f : features)
            text_.features += (text_.features.empty() ? "" : ", ") + f;
        auto_exposure_ = o.exposure == "auto";
        if (!auto_exposure_) text_.exposure = std::stof(o.exposure);
        renderer_.set_display(bgra, text_.exposure);
    }

    // Runs the loop until --frames or the window closes; `window` null: headless.
    int run(ViewWindow* window, Presenter* presenter, Overlay* overlay) {
        for (uint32_t frame = 0; o_.frames == 0 || frame < o_.frames; ++frame) {
            if (window && window->closed()) break;
            std::vector<ViewAction> actions;
            if (window) actions = window->poll(overlay->wants_mouse());
            for (const ScriptedAction& s : script_)
                if (s.frame == frame) actions.push_back(s.action);
            for (const ViewAction& a : actions) apply(a);
            if (restart_) {
                if (window_engine_) {
                    compare_stop_.store(true);
                    window_engine_->abandon("the view moved: the live compare was for the view "
                                            "before (press C again)");
                }
                renderer_.restart(camera_.camera(scene_.origin, width_, height_));
                restart_ = false;
                ++view_id_;
            }
            poll_jobs();

            const auto t0 = std::chrono::steady_clock::now();
            const uint64_t rays_before = renderer_.rays();
            const bool rendered = renderer_.frame();
            // --exposure auto: from the first whole pass, the earliest image of every pixel.
            if (auto_exposure_ && renderer_.spp() >= 1) set_auto_exposure();
            const bool last = o_.frames > 0 && frame + 1 == o_.frames;
            if (window_engine_) window_engine_->serve(renderer_, rendered && !last);
            if (presenter) {
                text_.spp = renderer_.spp();
                text_.pass_fraction = renderer_.pass_fraction();
                overlay->build(text_, show_overlay_);
                std::vector<uint8_t> capture;
                const Buffer& shown = picture_ ? *picture_ : renderer_.display_pixels();
                presenter->present(
                    shown, [&](VkCommandBuffer cmd) { overlay->record(cmd); },
                    last && !o_.screenshot.empty() ? &capture : nullptr);
                if (!capture.empty())
                    write_png(o_.screenshot, int(presenter->shown_width()),
                              int(capture.size() / 3 / presenter->shown_width()), capture);
            } else if (last && !o_.screenshot.empty()) {
                write_png(o_.screenshot, int(width_), int(height_), renderer_.display_rgb8());
            }
            const double seconds = seconds_since(t0);
            if (rendered) {
                times_.add(seconds, renderer_.frame_split(), renderer_.rays() - rays_before);
                text_.frame_ms = 1e3 * seconds;
                text_.mrays_per_s = double(renderer_.rays() - rays_before) / seconds * 1e-6;
            } else if (window) {
                // The accumulation is complete: wait for input instead of spinning.
                std::this_thread::sleep_for(std::chrono::milliseconds(10));
            }
        }
        // What the jobs were asked for is reported (and written) before the view exits.
        while (compare_job_ || pathdiff_job_) {
            // The window accumulates no more: the live compare takes what it has.
            if (window_engine_) window_engine_->serve(renderer_, false);
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            poll_jobs();
        }
        if (o_.headless)
            fmt::print("view --headless: {}\n",
                       times_.report(renderer_.spp(), renderer_.pass_fraction()));
        return 0;
    }

  private:
    void apply(const ViewAction& a) {
        const double per_pixel = kOrbitPerPixel / double(height_);
        const double view_height =
            2.0 * std::tan(0.5 * double(camera_.fov()) * glm::pi<double>() / 180.0);
        switch (a.kind) {
        case ViewAction::Orbit:
            camera_.orbit(-a.x * per_pixel, -a.y * per_pixel);
            break;
        case ViewAction::Pan:
            camera_.pan(-a.x / double(height_) * view_height, a.y / double(height_) * view_height);
            break;
        case ViewAction::Wheel:
            camera_.dolly(std::pow(kDollyPerNotch, a.y));
            break;
        case ViewAction::Fov:
            camera_.zoom_fov(-a.y * kFovPerNotch);
            break;
        case ViewAction::Click:
            start_pathdiff(a.x, a.y);
            return;
        case ViewAction::Key:
            if (key(a.key)) return;
            break;
        }
        restart_ = true;
        picture_.reset(); // a new view: the compare map no longer belongs to it
    }

    // Command keys; returns true when the camera did not move.
    bool key(char k) {
        switch (k) {
        case 'w':
            camera_.fly(0, 0, kFlyStep);
            return false;
        case 's':
            camera_.fly(0, 0, -kFlyStep);
            return false;
        case 'a':
            camera_.fly(-kFlyStep, 0, 0);
            return false;
        case 'd':
            camera_.fly(kFlyStep, 0, 0);
            return false;
        case 'q':
            camera_.fly(0, -kFlyStep, 0);
            return false;
        case 'e':
            camera_.fly(0, kFlyStep, 0);
            return false;
        case 'P':
            fmt::print("twinpath render {} --backend vulkan --vk-mode {} --seed {} --sampler {} "
                       "--width {} --height {} --max-depth {} --min-depth {} --spp {} {}\n",
                       o_.scene_path, vk_mode_name(renderer_.mode()), o_.progressive.seed,
                       sampler_name(o_.progressive.sampler), width_, height_,
                       scene_.params.max_depth, scene_.params.min_depth,
                       std::max(1u, renderer_.spp()), camera_.render_flags());
            std::fflush(stdout);
            break;
        case 'S':
            save();
            break;
        case 'H':
            show_overlay_ = !show_overlay_;
            break;
        case 'C':
            start_compare();
            break;
        case '[':
        case ']':
            text_.exposure += k == '[' ? -kExposureStep : kExposureStep;
            renderer_.set_display(bgra_, text_.exposure);
            break;
        case 'X':
            set_auto_exposure();
            break;
        case 27:
            picture_.reset();
            status({});
            break;
        }
        return true;
    }

    FlatScene current_scene() const {
        FlatScene s = scene_;
        s.params.camera = renderer_.camera();
        return s;
    }

    void status(std::vector<std::string> lines) {
        for (const std::string& l : lines) fmt::print("view: {}\n", l);
        std::fflush(stdout);
        text_.status = std::move(lines);
    }

    void save() {
        const std::string base = free_name(stem(o_.scene_path) + "_view");
        RenderResult r = renderer_.result();
        r.stats.scene = o_.scene_path;
        RenderOptions opt;
        opt.sampler = o_.progressive.sampler;
        write_exr(base + ".exr", render_exr(r, current_scene(), opt));
        const ExrImage img = r.film.to_exr();
        write_png(
            base + ".png", int(img.width), int(img.height),
            tonemap_srgb8(img.channel("R"), img.channel("G"), img.channel("B"), text_.exposure));
        status({fmt::format("saved {}.exr and {}.png ({} spp)", base, base, r.stats.spp)});
    }

    // The exposure that maps the accumulation's 99th percentile to white (image/exposure.h), as
    // render --exposure auto does.
    void set_auto_exposure() {
        auto_exposure_ = false;
        const ExrImage img = renderer_.result().film.to_exr();
        text_.exposure = auto_exposure_stops(img.channel("R"), img.channel("G"), img.channel("B"));
        renderer_.set_display(bgra_, text_.exposure);
        status({fmt::format("exposure {:+.2f} stops (auto, from {} spp)", text_.exposure,
                            renderer_.spp())});
    }

    void start_compare() {
        if (compare_job_) return status({"the live compare is still running"});
        if (renderer_.spp() < kMinCompareSpp)
            return status({fmt::format("C compares from {} spp on; the window has {}",
                                       kMinCompareSpp, renderer_.spp())});
        compare_view_id_ = view_id_;
        compare_stop_.store(false);
        window_engine_ =
            std::make_shared<WindowEngine>(current_scene(), o_.progressive.seed,
                                           o_.progressive.sampler, vk_mode_name(renderer_.mode()));
        compare_job_ =
            CpuJob::live_compare(current_scene(), window_engine_, o_.progressive.seed,
                                 o_.progressive.sampler, o_.threads, o_.verify, &compare_stop_);
    }

    void start_pathdiff(double x, double y) {
        if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
        if (pathdiff_job_) return status({"the last click's path logs are still being made"});
        VulkanOptions vk;
        vk.device = o_.device;
        vk.mode = renderer_.mode();
        const std::string prefix =
            fmt::format("{}_pixel_{}_{}", stem(o_.scene_path), uint32_t(x), uint32_t(y));
        pathdiff_job_ =
            CpuJob::pathdiff(current_scene(), uint32_t(x), uint32_t(y), o_.progressive.seed,
                             o_.progressive.sampler, o_.threads, vk, o_.scene_path, prefix);
    }

    void poll_jobs() {
        if (compare_job_) {
            if (std::optional<CpuJobOutcome> out = compare_job_->poll()) {
                compare_job_.reset();
                window_engine_.reset();
                // The map belongs to the view it was made for.
                if (!out->picture_rgb.empty() && compare_view_id_ == view_id_)
                    show_picture(out->picture_rgb);
                status(out->lines);
            } else {
                text_.status = {compare_job_->activity()};
            }
        }
        if (pathdiff_job_) {
            if (std::optional<CpuJobOutcome> out = pathdiff_job_->poll()) {
                pathdiff_job_.reset();
                status(out->lines);
            }
        }
    }

    // Shows an RGB8 picture of the film's size instead of the accumulation until Esc or a move.
    void show_picture(const std::vector<uint8_t>& rgb) {
        const size_t n = size_t(width_) * height_;
        picture_ = std::make_unique<Buffer>(ctx_, VkDeviceSize(n) * 4,
                                            VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
        auto* px = static_cast<uint32_t*>(picture_->mapped());
        for (size_t i = 0; i < n; ++i)
            px[i] =
                display_pack(uvec3(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]), bgra_ ? 1u : 0u);
    }

    const FlatScene& scene_;
    const ViewOptions& o_;
    const VulkanContext& ctx_;
    bool bgra_;
    ProgressiveRenderer renderer_;
    ViewCamera camera_;
    uint32_t width_, height_;
    std::vector<ScriptedAction> script_;
    OverlayText text_;
    FrameTimes times_;
    bool restart_ = false, show_overlay_ = true;
    bool auto_exposure_ = false; // --exposure auto, until the first whole pass
    std::unique_ptr<Buffer> picture_;
    std::unique_ptr<CpuJob> compare_job_, pathdiff_job_;
    // The live compare's side of the window (served every frame) and its stop (a camera move).
    std::shared_ptr<WindowEngine> window_engine_;
    std::atomic<bool> compare_stop_{false};
    uint64_t view_id_ = 0, compare_view_id_ = 0; // restarts so far; at the compare's start
};

} // namespace

int run_view(const FlatScene& scene, const ViewOptions& o) {
    const uint32_t w = scene.params.camera.width, h = scene.params.camera.height;
    if (o.headless) {
        const VulkanContext ctx(o.device, o.vk_mode);
        Viewer viewer(scene, o, ctx, false);
        return viewer.run(nullptr, nullptr, nullptr);
    }
    ViewWindow window(w, h, fmt::format("twinpath view {}", o.scene_path));
    const PresentationRequest presentation = window.presentation();
    const VulkanContext ctx(o.device, o.vk_mode, false, &presentation);
    Presenter presenter(ctx, w, h);
    Viewer viewer(scene, o, ctx, presenter.bgra());
    Overlay overlay(ctx, window, presenter);
    return viewer.run(&window, &presenter, &overlay);
}

} // namespace tp
