#include "render/render_header.h"

#include "render/sampler.h"
#include "scene/scene_hash.h"
#include "util/error.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstdlib>

namespace tp {

std::string format_sample_ranges(std::vector<SampleRange> ranges) {
    std::sort(ranges.begin(), ranges.end(), [](const SampleRange& a, const SampleRange& b) {
        return a.seed != b.seed ? a.seed < b.seed : a.begin < b.begin;
    });
    std::vector<SampleRange> joined;
    for (const SampleRange& r : ranges) {
        if (!joined.empty() && joined.back().seed == r.seed && joined.back().end == r.begin)
            joined.back().end = r.end;
        else
            joined.push_back(r);
    }
    std::string text;
    for (const SampleRange& r : joined)
        text += fmt::format("{}{}:{}-{}", text.empty() ? "" : ",", r.seed, r.begin, r.end);
    return text;
}

std::vector<SampleRange> parse_sample_ranges(const std::string& text, const std::string& where) {
    std::vector<SampleRange> ranges;
    size_t start = 0;
    while (start < text.size()) {
        const size_t end = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, end - start);
        unsigned long long seed = 0, b = 0, e = 0;
        char tail = 0;
        if (std::sscanf(item.c_str(), "%llu:%llu-%llu%c", &seed, &b, &e, &tail) != 3 ||
            seed > 0xffffffffull || b >= e)
            input_error("{}: '{}' is not a sample range SEED:BEGIN-END with BEGIN < END", where,
                        item);
        ranges.push_back({uint32_t(seed), b, e});
        start = end + 1;
    }
    if (ranges.empty()) input_error("{}: no sample range", where);
    return ranges;
}

std::string camera_description(const FlatScene& scene) {
    const Camera& c = scene.params.camera;
    const glm::dvec3 eye = scene.origin + glm::dvec3(c.eye);
    return fmt::format("eye {},{},{} forward {},{},{} up {},{},{} right {},{},{} "
                       "tan_half_fov_y {} aspect {}",
                       eye.x, eye.y, eye.z, c.forward.x, c.forward.y, c.forward.z, c.up.x, c.up.y,
                       c.up.z, c.right.x, c.right.y, c.right.z, c.tan_half_fov_y, c.aspect);
}

std::string settings_description(const FlatScene& scene, const DebugRequest& debug) {
    return fmt::format("min_depth {} max_depth {} integrator {}", scene.params.min_depth,
                       scene.params.max_depth, integrator_name(debug.integrator));
}

ExrImage render_exr(const RenderResult& r, const FlatScene& scene, const RenderOptions& options) {
    namespace h = header;
    ExrImage img = r.film.to_exr(options.film);
    const RenderStats& s = r.stats;
    img.integers[h::kSpp] = s.spp;
    img.integers[h::kSeed] = s.seed;
    if (!s.sample_ranges.empty()) {
        img.strings[h::kSampleRanges] = format_sample_ranges(s.sample_ranges);
    } else if (s.spp > 0) {
        const uint64_t begin = options.sample_offset;
        img.strings[h::kSampleRanges] = format_sample_ranges({{s.seed, begin, begin + s.spp}});
    }
    img.strings[h::kBackend] = s.mode.empty() ? s.backend : s.backend + "/" + s.mode;
    img.strings[h::kDevice] = s.device;
    img.strings[h::kScene] = s.scene;
    img.strings[h::kSceneHash] = scene_hash(scene);
    img.strings[h::kCamera] = camera_description(scene);
    // The sampler changes what a sample estimates jointly with its neighbours: parts of
    // different samplers are not parts of one render. The film wrote the variance estimator.
    img.strings[h::kSettings] =
        settings_description(scene, options.debug) + " sampler " + sampler_name(options.sampler);
    img.strings[h::kSampler] = sampler_name(options.sampler);
    img.reals[h::kRenderTime] = s.wall_time_s;
    if (options.debug.integrator != INTEGRATOR_PATH)
        img.strings[h::kIntegrator] = integrator_name(options.debug.integrator);
    if (options.debug.aov) add_aov_layers(img, r.debug.aovs);
    return img;
}

PathLogInfo path_log_info(const RenderResult& result, const FlatScene& scene,
                          const std::string& scene_path, const DebugRequest& debug) {
    PathLogInfo info;
    info.backend = result.stats.backend;
    info.mode = result.stats.mode;
    info.device = result.stats.device;
    info.scene = scene_path;
    info.seed = result.stats.seed;
    info.sampler = result.stats.sampler;
    info.width = scene.params.camera.width;
    info.height = scene.params.camera.height;
    info.spp = result.stats.spp;
    info.max_depth = scene.params.max_depth;
    info.min_depth = scene.params.min_depth;
    info.pixel_x = debug.pixel_x;
    info.pixel_y = debug.pixel_y;
    info.dropped = result.debug.dropped;
    info.origin = scene.origin;
    return info;
}

} // namespace tp
