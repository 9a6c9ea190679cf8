#include "vulkan_rt/device/gpu_timer.h"

#include "vulkan_rt/device/vk_error.h"

namespace tp {

GpuTimer::GpuTimer(const VulkanContext& ctx)
    : device_(ctx.device()), period_ns_(double(ctx.limits().timestampPeriod)),
      mask_(ctx.timestamp_valid_bits() >= 64 ? ~0ull
                                             : (1ull << ctx.timestamp_valid_bits()) - 1ull) {
    if (ctx.timestamp_valid_bits() == 0) return;
    VkQueryPoolCreateInfo qi{};
    qi.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    qi.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qi.queryCount = 2;
    vk_check(vkCreateQueryPool(device_, &qi, nullptr, &pool_), "creating a timestamp query pool");
}

GpuTimer::~GpuTimer() {
    if (pool_) vkDestroyQueryPool(device_, pool_, nullptr);
}

void GpuTimer::record_begin(VkCommandBuffer cmd) const {
    if (!pool_) return;
    vkCmdResetQueryPool(cmd, pool_, 0, 2);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_, 0);
}

void GpuTimer::record_end(VkCommandBuffer cmd) const {
    if (!pool_) return;
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, 1);
}

double GpuTimer::read_seconds() const {
    if (!pool_) return 0.0;
    uint64_t t[2] = {0, 0};
    vk_check(vkGetQueryPoolResults(device_, pool_, 0, 2, sizeof(t), t, sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
             "reading GPU timestamps");
    const uint64_t ticks = ((t[1] & mask_) - (t[0] & mask_)) & mask_;
    return double(ticks) * period_ns_ * 1e-9;
}

} // namespace tp
