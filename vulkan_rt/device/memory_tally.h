// The device memory a VulkanContext holds: Buffer and Image, the only callers of
// vkAllocateMemory, add each allocation here and take it away when they free it. The peak is
// RenderStats::device_memory_peak_bytes.
#pragma once

#include <atomic>
#include <cstdint>

namespace tp {

class MemoryTally {
  public:
    void add(uint64_t bytes);
    void remove(uint64_t bytes);
    uint64_t held() const { return held_.load(); }
    // The most held at once since the tally began or since restart_peak().
    uint64_t peak() const { return peak_.load(); }
    // Starts a new peak from what is held now (a render's own peak on a device kept open).
    void restart_peak() { peak_.store(held_.load()); }

  private:
    // Atomic: the devices of a group render on threads of their own, and a context's
    // allocations may come from more than one thread.
    std::atomic<uint64_t> held_{0}, peak_{0};
};

} // namespace tp
