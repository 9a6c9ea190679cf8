#include "vulkan_rt/renderer/sample_share.h"

#include <algorithm>
#include <cmath>

namespace tp {

SampleShare::SampleShare(uint32_t begin, uint32_t count, size_t devices)
    : next_(begin), end_(uint64_t(begin) + count), total_(count), rates_(devices, 0.0) {}

SampleShare::Range SampleShare::take(size_t device, double rate) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (next_ >= end_) return {};
    rates_[device] = rate;
    const double n = double(rates_.size());
    const uint64_t left = end_ - next_;
    uint64_t count;
    if (rate <= 0) {
        count = uint64_t(std::ceil(double(total_) / (8.0 * n)));
    } else {
        // Devices without a rate yet count at the mean of those with one.
        double known = 0, with_rate = 0;
        for (double r : rates_)
            if (r > 0) known += r, ++with_rate;
        const double all = known + (n - with_rate) * known / with_rate;
        count = uint64_t(std::ceil(double(left) * rate / all / 2.0));
    }
    count = std::clamp<uint64_t>(count, 1, left);
    const Range r{uint32_t(next_), uint32_t(count)};
    next_ += count;
    return r;
}

void SampleShare::close() {
    const std::lock_guard<std::mutex> lock(mutex_);
    next_ = end_;
}

} // namespace tp
