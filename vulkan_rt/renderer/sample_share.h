// One render's sample range shared among several devices (--device all, docs/farm.md): each
// device asks for its next range when it finishes the last one, and gets a part of what is
// left in proportion to its measured rate (guided self-scheduling, Polychronopoulos & Kuck
// 1987, weighted by rate): half of its rate-proportional share of the remainder, at least one
// sample per pixel. Ranges shrink as the render nears its end, so the devices finish within
// about one small range of each other however their speeds differ, and a device that turns
// out slower than measured delays the end by at most its last range. The first range of each
// device, before any rate is known, is 1/8 of an equal share.
#pragma once

#include <cstdint>
#include <mutex>
#include <vector>

namespace tp {

class SampleShare {
  public:
    // Samples [begin, begin + count) for `devices` devices.
    SampleShare(uint32_t begin, uint32_t count, size_t devices);

    struct Range {
        uint32_t begin = 0, count = 0; // count 0: nothing left
    };
    // The next range for `device`, whose rate so far is `rate` (any unit shared by all devices,
    // 0 before its first range). Thread-safe.
    Range take(size_t device, double rate);
    // No more ranges for anyone (a device failed, or the render was interrupted).
    void close();

  private:
    std::mutex mutex_;
    uint64_t next_, end_;
    uint32_t total_;
    std::vector<double> rates_;
};

} // namespace tp
