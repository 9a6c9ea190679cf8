// `twinpath merge`: renders of disjoint sample ranges of one scene, combined into the image one
// render of all their samples would have made (docs/farm.md). Every part must come from the
// same scene, camera, size, settings and backend; ranges of one seed must not overlap, ranges
// of different seeds are independent samples of the same estimator and are accepted.
#pragma once

#include "image/exr_io.h"
#include "render/film.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tp {

// Parts are added one at a time, so that 64 full-HD parts need one image of accumulators in
// memory rather than all 64 images.
//   X with a variance.X channel (R, G, B): the spp-weighted mean of the parts' means;
//   variance.X: pooled from each part's sample variance and mean, not averaged (below);
//   id.*: the first part's (every part traces the same pixel centres);
//   any other channel (albedo.*, normal.*, depth.Z): the spp-weighted mean;
//   header: the parts' sample ranges joined, the total spp, the summed render time, the
//   devices, and one line per part in twinpath:parts.
//
// Pooling (Chan, Golub & LeVeque 1979, the pairwise update of render/moments.h): a part with n
// samples per pixel, mean m and variance of the mean v has the sum of squared deviations
// M2 = v n (n - 1); adding it to accumulated (N, mean M, M2_acc) with d = m - M gives
//   M2_acc + M2 + d^2 N n / (N + n),   and in the end variance of the mean = M2 / ((N - 1) N),
// which equals sum M2_i + sum n_i (m_i - m_all)^2 over all parts, the between-part term
// included. That holds for twinpath:variance_estimator "samples" (the samples of a pixel are
// independent).
//
// Parts of twinpath:variance_estimator "batches" (the Sobol sampler, render/film.h) carry the
// mean of each batch (batchB.*) and the sample variance (sample_variance.*). Sample s is in
// batch s mod K whatever part renders it, so batch b of the whole holds the samples of batch b
// of every part: its mean is the count-weighted mean of the parts' batch-b means, the counts
// follow from each part's sample ranges, and the random-group estimator over those batches
// (render/moments.h) is the one a single render of all the samples would have computed, up to
// the float rounding of the files. sample_variance.* pools by the pairwise update as above
// (M2 = s^2 (n - 1)); twinpath:variance_dof is K' - 1 over the batches that hold samples.
// Parts of different estimators or batch counts are refused (docs/sampling.md), and so are
// batch-estimated parts of the lean film (twinpath:film "lean", render/film.h), which keep no
// batch means. Parts without twinpath:film (written before it) are full films.
class RenderMerger {
  public:
    // Checks `image` against the parts added before and adds it. InputError (exit code 2)
    // naming `path` and the header field or channel: a field missing, a different size, scene
    // hash, camera, settings, backend, variance estimator, batch count or channel set (a
    // batch-estimated part without its batch and sample variance channels), twinpath:spp unequal
    // to the length of its sample ranges, or samples that overlap an earlier part's of the same
    // seed.
    void add(const std::string& path, const ExrImage& image);

    // The merged image in the given layout (render/film.h): full keeps the batch means, so that
    // it can be merged again; lean drops them. InputError when no part was added.
    ExrImage result(FilmLayout layout = FilmLayout::full) const;

  private:
    // A channel without variance: sum over parts of n * value. One with variance (R, G, B):
    // the pooled mean and M2, and for batch-estimated parts each batch's sum of values
    // (pixel-major, K per pixel).
    struct Channel {
        std::vector<double> sum;
        std::vector<double> mean, m2;
        std::vector<double> batch_sum;
    };
    bool batches() const { return batch_count_.size() > 0; }
    struct Range {
        uint32_t seed;
        uint64_t begin, end;
        std::string path;
    };
    std::string first_path_;
    ExrImage first_; // the first part's size, header strings and id channels
    std::map<std::string, Channel> channels_;
    std::vector<Range> ranges_;
    std::vector<std::string> part_lines_, devices_;
    std::string estimator_;
    std::vector<uint64_t> batch_count_; // batch-estimated parts: samples per pixel in batch b
    uint64_t n_ = 0;                    // samples per pixel so far
    double render_time_s_ = 0;
};

// Reads the files one at a time into a RenderMerger.
ExrImage merge_files(const std::vector<std::string>& paths, FilmLayout layout = FilmLayout::full);

} // namespace tp
