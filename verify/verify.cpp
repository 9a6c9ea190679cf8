#include "verify/verify.h"

#include "util/clock.h"
#include "util/error.h"
#include "verify/at_once.h"
#include "verify/summary.h"

#include <chrono>

namespace tp {
namespace {

using Clock = std::chrono::steady_clock;

void say(const VerifyObserver& observer, const std::vector<std::string>& lines) {
    if (observer.line)
        for (const std::string& l : lines) observer.line(l);
}

// Runs one phase's renders on every engine at once, with its progress.
std::vector<EngineRun> phase(const std::vector<Engine*>& engines,
                             const std::vector<EngineRequest>& requests, bool pilot,
                             std::atomic<bool>& stop, const VerifyObserver& observer) {
    std::vector<double> fractions(engines.size(), 0.0);
    const std::string name = pilot ? "pilots" : "images";
    std::vector<EngineRun> runs = render_at_once(
        engines, requests,
        [pilot](Engine& e, const EngineRequest& r) { return pilot ? e.pilot(r) : e.render(r); },
        stop,
        [&](size_t k, double f) {
            fractions[k] = f;
            if (observer.progress) observer.progress(name, fractions);
        });
    if (stop.load()) runtime_error("verify: stopped during the {}", name);
    return runs;
}

} // namespace

bool VerifyResult::different() const {
    for (const PairVerdict& v : verdicts)
        if (v.compare.different) return true;
    return false;
}

VerifyResult verify(const std::vector<Engine*>& engines, const VerifyOptions& o,
                    const VerifyObserver& observer) {
    std::atomic<bool> own_stop{false};
    std::atomic<bool>& stop = o.stop ? *o.stop : own_stop;
    VerifyResult v;
    v.alpha = o.plan.alpha;
    v.request = o.plan;
    std::vector<std::optional<uint32_t>> own;
    for (Engine* e : engines) {
        v.labels.push_back(e->label());
        own.push_back(e->own_seed());
    }
    for (size_t a = 0; a < engines.size(); ++a)
        for (size_t b = a + 1; b < engines.size(); ++b) v.pairs.emplace_back(a, b);
    v.seeds = verify_seeds(o.seed, own);

    // 1. Pilots.
    const Clock::time_point t0 = Clock::now();
    std::vector<EngineRequest> requests(engines.size());
    for (size_t k = 0; k < engines.size(); ++k) {
        requests[k].spp = o.pilot_spp;
        requests[k].seed = v.seeds.pilot[k];
    }
    v.pilots = phase(engines, requests, true, stop, observer);
    v.pilot_wall_s = seconds_since(t0);
    std::vector<RgbImage> pilot_images;
    for (size_t k = 0; k < engines.size(); ++k) {
        pilot_images.push_back(rgb_image_from_exr(v.pilots[k].image, v.labels[k] + " pilot"));
        v.costs.push_back(engine_cost(v.pilots[k], engines[k]->lane()));
    }
    v.model = noise_power_model(estimate_noise(pilot_images));
    say(observer, {pilot_line(v)});

    // 2. Plan; the budget is for the pilots and the images together.
    PlanRequest request = o.plan;
    if (request.budget_s) request.budget_s = std::max(0.0, *request.budget_s - v.pilot_wall_s);
    v.plan = plan_samples(v.model, v.costs, v.pairs, request);
    say(observer, plan_lines(v));

    // 3. Images.
    const Clock::time_point t1 = Clock::now();
    for (size_t k = 0; k < engines.size(); ++k) {
        requests[k].spp = v.plan.spp[k];
        requests[k].seed = v.seeds.image[k];
    }
    v.images = phase(engines, requests, false, stop, observer);
    v.image_wall_s = seconds_since(t1);
    for (size_t k = 0; k < engines.size(); ++k)
        v.rgb.push_back(rgb_image_from_exr(v.images[k].image, v.labels[k]));
    say(observer, {images_line(v)});

    // 4. Compare every pair.
    CompareOptions compare;
    compare.alpha = o.plan.alpha / double(v.pairs.size());
    std::vector<uint32_t> spp;
    for (const RgbImage& img : v.rgb) spp.push_back(uint32_t(img.spp.value_or(1)));
    for (const auto& [a, b] : v.pairs) {
        PairVerdict pv;
        pv.a = a;
        pv.b = b;
        pv.compare = compare_images(v.rgb[a], v.rgb[b], compare);
        const std::vector<std::pair<size_t, size_t>> one = {{a, b}};
        pv.power = pairs_power(v.model, spp, one, o.plan.detect, v.plan.level);
        pv.detectable = pairs_detectable(v.model, spp, one, v.plan.level, o.plan.power);
        v.verdicts.push_back(std::move(pv));
        say(observer, verdict_lines(v, v.verdicts.back()));
    }

    // 5. Triage.
    const Clock::time_point t2 = Clock::now();
    if (o.triage)
        for (PairVerdict& pv : v.verdicts) {
            if (!pv.compare.different) continue;
            pv.triage =
                triage(*engines[pv.a], *engines[pv.b], pv.compare, v.seeds.log, o.max_depth);
            say(observer, triage_lines(v, pv));
        }
    v.triage_wall_s = seconds_since(t2);
    return v;
}

} // namespace tp
