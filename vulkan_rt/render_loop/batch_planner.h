// Splits a render into GPU submissions that each take about `target_seconds`, so that no
// submission comes near a display watchdog (Windows TDR: 2 s) and --time-limit and progress
// stay responsive. A pass traces `samples` samples of every pixel, as one submission or as
// bands of rows; the work of the next submission (pixels x samples) follows the throughput
// measured on the previous ones, changing by at most 4x at a time. A pass that the measured
// throughput finishes within `whole_pass_seconds` is never split into bands, however short
// `target_seconds` is (the viewer: a frame is the whole image unless that takes too long). A
// device that had to cut a batch short (lavapipe's per-invocation loop budget,
// shaders/render_items.glsl) gets at most half as many samples per pixel in the batches after it.
#pragma once

#include <cstdint>

namespace tp {

struct Batch {
    uint32_t sample_begin;
    uint32_t sample_count;
    uint32_t row_begin;
    uint32_t row_end;
};

class BatchPlanner {
  public:
    // `initial_work`: pixel-samples of the first submission; a render of several ranges passes
    // on what the previous range's planner learnt (work()). `max_work`: of any submission.
    // `whole_pass_seconds`: the longest a pass of one sample per pixel may take, at the
    // throughput measured so far, and still be one batch (0: as long as target_seconds).
    BatchPlanner(uint32_t width, uint32_t height, uint32_t spp, double target_seconds,
                 uint64_t initial_work = kInitialWork, uint64_t max_work = kMaxWork,
                 double whole_pass_seconds = 0);

    bool done() const { return samples_done_ >= stop_; }
    // Ends the render (for now) after `spp` samples per pixel: a checkpoint; at most the total.
    void stop_at(uint32_t spp) { stop_ = spp < spp_ ? spp : spp_; }
    Batch next() const;
    // The batch from next() finished in `seconds` (wall time of its submissions); `cut_short`:
    // it needed repeated dispatches.
    void completed(const Batch& b, double seconds, bool cut_short = false);

    bool at_pass_boundary() const { return row_ == 0; }
    uint32_t samples_done() const { return samples_done_; } // whole passes
    // The share of the rows of the pass under way that have its samples (0 at a boundary).
    double pass_fraction() const { return double(row_) / double(height_); }
    double fraction_done() const;
    uint64_t work() const { return work_; } // pixel-samples planned per submission
    uint32_t max_samples() const { return max_samples_; }

    // Samples per pixel in one pass at most: the resolve pass (shaders/resolve.comp) walks a
    // pixel slot's samples of a batch in one loop, within lavapipe's loop budget.
    static constexpr uint32_t kMaxSamplesPerBatch = 1024;
    // Pixel-samples per submission at most, whatever the device: each is a work item whose
    // estimate waits in the sample buffer (16 bytes) for the resolve pass (1 GiB at this bound).
    static constexpr uint64_t kMaxWork = uint64_t(1) << 26;
    static constexpr uint64_t kInitialWork = 16384;

  private:
    uint32_t width_, height_, spp_;
    uint32_t stop_;
    double target_;
    uint64_t max_work_;
    double whole_pass_;     // seconds; see the constructor
    bool measured_ = false; // a batch has completed: work_ follows the device's throughput
    uint64_t work_;
    uint32_t max_samples_ = kMaxSamplesPerBatch;
    uint32_t samples_done_ = 0;
    uint32_t row_ = 0;          // next row of the current pass
    uint32_t pass_samples_ = 0; // samples per pixel of the current pass (0: not started)
};

} // namespace tp
