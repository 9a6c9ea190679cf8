// GPU time of a command buffer's work from two timestamp queries (vkCmdWriteTimestamp), for
// the "gpu_time_s" statistic. Inactive on queues without timestamps (timestampValidBits 0).
#pragma once

#include "vulkan_rt/device/context.h"

namespace tp {

class GpuTimer {
  public:
    explicit GpuTimer(const VulkanContext& ctx);
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    bool active() const { return pool_ != VK_NULL_HANDLE; }
    void record_begin(VkCommandBuffer cmd) const; // before the timed commands
    void record_end(VkCommandBuffer cmd) const;   // after them
    // Seconds between the two timestamps of the last completed submission.
    double read_seconds() const;

  private:
    VkDevice device_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    double period_ns_;
    uint64_t mask_;
};

} // namespace tp
