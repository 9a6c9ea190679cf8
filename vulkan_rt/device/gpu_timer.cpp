#include "vulkan_rt/device/gpu_timer.h"

#include "vulkan_rt/device/vk_error.h"

#include <algorithm>

namespace tp {

GpuTimer::GpuTimer(const VulkanContext& ctx, uint32_t marks)
    : device_(ctx.device()), marks_(std::max(marks, 2u)),
      period_ns_(double(ctx.limits().timestampPeriod)),
      mask_(ctx.timestamp_valid_bits() >= 64 ? ~0ull
                                             : (1ull << ctx.timestamp_valid_bits()) - 1ull) {
    if (ctx.timestamp_valid_bits() == 0) return;
    VkQueryPoolCreateInfo qi{};
    qi.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    qi.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qi.queryCount = marks_;
    vk_check(vkCreateQueryPool(device_, &qi, nullptr, &pool_), "creating a timestamp query pool");
}

GpuTimer::~GpuTimer() {
    if (pool_) vkDestroyQueryPool(device_, pool_, nullptr);
}

void GpuTimer::record_mark(VkCommandBuffer cmd, uint32_t i) const {
    if (!pool_) return;
    if (i == 0) {
        vkCmdResetQueryPool(cmd, pool_, 0, marks_);
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_, 0);
    } else {
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, i);
    }
}

std::vector<double> GpuTimer::read_intervals() const {
    std::vector<double> seconds(marks_ - 1, 0.0);
    if (!pool_) return seconds;
    std::vector<uint64_t> t(marks_, 0);
    vk_check(vkGetQueryPoolResults(device_, pool_, 0, marks_, t.size() * sizeof(uint64_t), t.data(),
                                   sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
             "reading GPU timestamps");
    for (uint32_t i = 0; i + 1 < marks_; ++i) {
        const uint64_t ticks = ((t[i + 1] & mask_) - (t[i] & mask_)) & mask_;
        seconds[i] = double(ticks) * period_ns_ * 1e-9;
    }
    return seconds;
}

} // namespace tp
