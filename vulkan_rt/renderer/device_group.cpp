#include "vulkan_rt/renderer/device_group.h"

#include "util/error.h"
#include "vulkan_rt/compute_mode/compute_renderer.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/device/device_info.h"
#include "vulkan_rt/pipeline_mode/pipeline_renderer.h"
#include "vulkan_rt/renderer/sample_share.h"

#include <fmt/core.h>

#include <algorithm>
#include <exception>
#include <thread>

namespace tp {

RenderResult render_on_devices(const FlatScene& scene, const RenderOptions& options,
                               const VulkanOptions& vk) {
    if (options.debug.active())
        input_error("--device {}: the debug outputs (--aov, --debug-log, --integrator) are "
                    "rendered on one device",
                    vk.device);
    if (options.time_limit_s > 0)
        input_error("--device {}: --time-limit is for one device; give --spp", vk.device);
    if (!options.checkpoints.empty()) input_error("checkpoints are for one device");
    const std::vector<DeviceInfo> devices = select_devices(list_vulkan_devices(), vk.device);
    const VkMode mode = resolve_common_mode(vk.mode, devices);

    SampleShare share(options.sample_offset, scene.spp, devices.size());
    std::vector<RenderResult> parts(devices.size());
    std::vector<std::exception_ptr> errors(devices.size());
    std::vector<std::thread> threads;
    for (size_t i = 0; i < devices.size(); ++i)
        threads.emplace_back([&, i] {
            try {
                const VulkanContext ctx(std::to_string(devices[i].index), mode,
                                        vk.pipeline_statistics);
                RenderOptions o = options;
                o.progress = nullptr; // one bar for all devices would need its own lock
                o.sample_source = [&share, i](double rate) {
                    const SampleShare::Range r = share.take(i, rate);
                    return RenderOptions::SampleGrant{r.begin, r.count};
                };
                parts[i] = mode == VkMode::pipeline ? render_pipeline(ctx, scene, o)
                                                    : render_compute(ctx, scene, o, vk.bvh);
                if (ctx.instance().validation_messages() > 0)
                    runtime_error("the Vulkan validation layer reported {} message(s) on {}",
                                  ctx.instance().validation_messages(), devices[i].name);
                if (options.stop_requested()) share.close();
            } catch (...) {
                errors[i] = std::current_exception();
                share.close();
            }
        });
    for (std::thread& t : threads) t.join();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);

    RenderResult result;
    result.film = std::move(parts.front().film);
    result.stats = parts.front().stats;
    RenderStats& st = result.stats;
    st.devices.clear();
    st.device.clear();
    st.spp = 0;
    st.samples = st.nan_samples = 0;
    st.rays = {};
    st.gpu_time_s = 0;
    st.wall_time_s = 0;
    st.sample_ranges.clear();
    for (size_t i = 0; i < parts.size(); ++i) {
        const RenderStats& p = parts[i].stats;
        if (i > 0) result.film.merge(parts[i].film);
        DeviceShare d;
        d.device = fmt::format("{}: {}", devices[i].index, devices[i].name);
        d.spp = p.spp;
        d.ranges = p.sample_ranges;
        d.wall_time_s = p.wall_time_s;
        d.gpu_time_s = p.gpu_time_s;
        d.rays = p.rays;
        d.samples = p.samples;
        st.devices.push_back(d);
        st.device += (i ? "; " : "") + p.device;
        st.spp += p.spp;
        st.samples += p.samples;
        st.nan_samples += p.nan_samples;
        st.rays += p.rays;
        // Devices render side by side: the render takes as long as the slowest of them.
        st.wall_time_s = std::max(st.wall_time_s, p.wall_time_s);
        // Each device holds its own copy of the scene: the peak is the largest device's.
        st.device_memory_peak_bytes =
            std::max(st.device_memory_peak_bytes, p.device_memory_peak_bytes);
        st.gpu_time_s = st.gpu_time_s < 0 || p.gpu_time_s < 0 ? -1.0 : st.gpu_time_s + p.gpu_time_s;
        st.sample_ranges.insert(st.sample_ranges.end(), p.sample_ranges.begin(),
                                p.sample_ranges.end());
    }
    return result;
}

} // namespace tp
