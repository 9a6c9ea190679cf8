// GPU time of the parts of a submission from timestamp queries (vkCmdWriteTimestamp): marks
// 0, 1, ..., n - 1 recorded between its parts give the seconds of each part, for the
// "gpu_time_s" statistic and the viewer's per-frame split. Inactive on queues without
// timestamps (timestampValidBits 0).
#pragma once

#include "vulkan_rt/device/context.h"

#include <vector>

namespace tp {

class GpuTimer {
  public:
    // `marks`: the timestamps each submission records, at least 2.
    GpuTimer(const VulkanContext& ctx, uint32_t marks);
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    bool active() const { return pool_ != VK_NULL_HANDLE; }
    // Mark `i`: mark 0 as the commands after it start, the others once the commands before
    // them have finished. Every mark is recorded once per submission, in order.
    void record_mark(VkCommandBuffer cmd, uint32_t i) const;
    // Seconds from mark i to mark i + 1 of the last completed submission, for each i (zeros
    // when inactive).
    std::vector<double> read_intervals() const;

  private:
    VkDevice device_;
    uint32_t marks_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    double period_ns_;
    uint64_t mask_;
};

} // namespace tp
