#include "view/window_engine.h"

#include "render/render_header.h"
#include "util/error.h"

namespace tp {

WindowEngine::WindowEngine(FlatScene scene, uint32_t seed, uint32_t sampler, std::string mode)
    : scene_(std::move(scene)), seed_(seed), sampler_(sampler), mode_(std::move(mode)) {}

EngineRun WindowEngine::pilot(const EngineRequest& request) {
    return wait(request, true);
}

EngineRun WindowEngine::render(const EngineRequest& request) {
    return wait(request, false);
}

EngineRun WindowEngine::wait(const EngineRequest& request, bool pilot) {
    std::future<EngineRun> done;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (!abandoned_.empty()) runtime_error("{}", abandoned_);
        pending_.emplace();
        pending_->request = &request;
        pending_->pilot = pilot;
        done = pending_->done.get_future();
    }
    return done.get();
}

void WindowEngine::serve(const ProgressiveRenderer& renderer, bool accumulating) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!pending_) return;
    const EngineRequest& rq = *pending_->request;
    const uint32_t spp = renderer.spp();
    const bool stopped = rq.stop && rq.stop->load();
    if (!pending_->pilot && spp < rq.spp && accumulating && !stopped) {
        if (rq.progress) rq.progress(double(spp) / double(rq.spp));
        return;
    }
    EngineRun run;
    run.result = renderer.result();
    RenderOptions opt;
    opt.seed = seed_;
    opt.sampler = sampler_;
    run.image = render_exr(run.result, scene_, opt);
    // The accumulation's time since its start; it was set up before that.
    run.sampling_s = run.result.stats.wall_time_s;
    run.kept_spp = pending_->pilot ? spp : 0;
    run.device = run.result.stats.device + " (" + mode_ + ")";
    if (rq.progress) rq.progress(1.0);
    pending_->done.set_value(std::move(run));
    pending_.reset();
}

void WindowEngine::abandon(const std::string& why) {
    const std::lock_guard<std::mutex> lock(mutex_);
    abandoned_ = why;
    if (!pending_) return;
    pending_->done.set_exception(std::make_exception_ptr(RuntimeError(why)));
    pending_.reset();
}

} // namespace tp
