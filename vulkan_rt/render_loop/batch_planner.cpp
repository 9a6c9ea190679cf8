#include "vulkan_rt/render_loop/batch_planner.h"

#include <algorithm>

namespace tp {

BatchPlanner::BatchPlanner(uint32_t width, uint32_t height, uint32_t spp, double target_seconds,
                           uint64_t initial_work, uint64_t max_work, double whole_pass_seconds)
    : width_(width), height_(height), spp_(spp), stop_(spp), target_(target_seconds),
      max_work_(std::max<uint64_t>(max_work, 1)), whole_pass_(whole_pass_seconds),
      work_(std::clamp<uint64_t>(initial_work, 1, max_work_)) {}

Batch BatchPlanner::next() const {
    const uint64_t pixels = uint64_t(width_) * height_;
    uint32_t samples = pass_samples_;
    if (row_ == 0) { // a new pass: as many samples as the planned work covers, at least one
        const uint64_t fit = std::max<uint64_t>(work_ / pixels, 1);
        samples = uint32_t(std::min<uint64_t>({fit, max_samples_, stop_ - samples_done_}));
    }
    uint32_t rows = height_ - row_;
    // work_ takes target_ seconds, so a whole pass at that throughput takes
    // target_ * pixels * samples / work_; the first batch's work_ is a guess, not a measurement.
    const uint64_t pass_work = pixels * samples;
    const bool whole = row_ == 0 && measured_ && pass_work <= max_work_ &&
                       double(pass_work) * target_ <= whole_pass_ * double(work_);
    if (!whole && uint64_t(width_) * rows * samples > work_)
        rows = uint32_t(std::clamp<uint64_t>(work_ / (uint64_t(width_) * samples), 1, rows));
    return {samples_done_, samples, row_, row_ + rows};
}

void BatchPlanner::completed(const Batch& b, double seconds, bool cut_short) {
    if (cut_short) max_samples_ = std::max(1u, b.sample_count / 2);
    const uint64_t done = uint64_t(width_) * (b.row_end - b.row_begin) * b.sample_count;
    const double wanted = seconds > 0 ? double(done) * target_ / seconds : double(work_) * 4.0;
    work_ = uint64_t(std::clamp(wanted, double(work_) / 4.0, double(work_) * 4.0));
    work_ = std::clamp<uint64_t>(work_, 1, max_work_);
    measured_ = measured_ || seconds > 0;
    pass_samples_ = b.sample_count;
    row_ = b.row_end;
    if (row_ >= height_) {
        row_ = 0;
        samples_done_ += b.sample_count;
        pass_samples_ = 0;
    }
}

double BatchPlanner::fraction_done() const {
    const double pass = double(row_) / double(height_) * double(pass_samples_);
    return (double(samples_done_) + pass) / double(spp_);
}

} // namespace tp
