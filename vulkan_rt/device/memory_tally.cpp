#include "vulkan_rt/device/memory_tally.h"

namespace tp {

void MemoryTally::add(uint64_t bytes) {
    const uint64_t now = held_.fetch_add(bytes) + bytes;
    uint64_t peak = peak_.load();
    while (now > peak && !peak_.compare_exchange_weak(peak, now)) {
    }
}

void MemoryTally::remove(uint64_t bytes) {
    held_.fetch_sub(bytes);
}

} // namespace tp
