#include "compare/merge.h"

#include "render/film.h"
#include "render/moments.h"
#include "render/render_header.h"
#include "util/error.h"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>

namespace tp {
namespace {

namespace h = header;

const std::string& text_field(const std::string& path, const ExrImage& img, const char* key) {
    const auto it = img.strings.find(key);
    if (it == img.strings.end())
        input_error("{}: no {} header attribute (not a twinpath render, or one written before "
                    "renders recorded it)",
                    path, key);
    return it->second;
}

int64_t int_field(const std::string& path, const ExrImage& img, const char* key) {
    const auto it = img.integers.find(key);
    if (it == img.integers.end()) input_error("{}: no {} header attribute", path, key);
    return it->second;
}

bool starts_with(const std::string& s, const char* prefix) {
    return s.rfind(prefix, 0) == 0;
}

bool is_id(const std::string& channel) {
    return starts_with(channel, "id.");
}

// Channels that are read with their colour channel, not merged on their own.
bool is_moment(const std::string& channel) {
    return starts_with(channel, "variance.") || starts_with(channel, "sample_variance.") ||
           (starts_with(channel, "batch") && channel.size() > 5 && std::isdigit(channel[5]));
}

// Batches of a batch-estimated part: batch0.R, batch1.R, ... up to the first missing one.
uint32_t batch_layers(const ExrImage& img) {
    uint32_t k = 0;
    while (img.has(batch_channel(k, 0))) ++k;
    return k;
}

// 0, 1, 2 for the colour channels R, G, B; -1 for any other.
int colour_index(const std::string& channel) {
    for (int c = 0; c < 3; ++c)
        if (channel == std::string(1, "RGB"[c])) return c;
    return -1;
}

// Samples s in [begin, end) with s mod k == b.
uint64_t batch_samples(uint64_t begin, uint64_t end, uint32_t b, uint32_t k) {
    auto below = [&](uint64_t x) { return (x + k - 1 - b) / k; }; // s in [0, x)
    return below(end) - below(begin);
}

} // namespace

void RenderMerger::add(const std::string& path, const ExrImage& img) {
    // Fields every part must have, and must have equal to the first part's.
    static const char* const kSame[] = {h::kSceneHash, h::kCamera, h::kSettings, h::kBackend,
                                        h::kVarianceEstimator};
    for (const char* key : kSame) text_field(path, img, key);
    const std::string& estimator = img.strings.at(h::kVarianceEstimator);
    const bool batch_part = estimator == kVarianceFromBatches;
    if (!batch_part && estimator != kVarianceFromSamples)
        input_error("{}: {} is '{}'; merge combines '{}' and '{}' estimates", path,
                    h::kVarianceEstimator, estimator, kVarianceFromSamples, kVarianceFromBatches);
    const uint32_t k = batch_part ? batch_layers(img) : 0;
    if (const auto film = img.strings.find(h::kFilm);
        batch_part && film != img.strings.end() &&
        film->second != film_layout_name(FilmLayout::full))
        input_error("{}: {} is '{}': a {} Sobol render keeps no batch means, which merge needs to "
                    "rebuild the batch estimate of the parts; render the parts with --film full "
                    "(docs/farm.md)",
                    path, h::kFilm, film->second, film->second);
    if (batch_part) {
        std::vector<std::string> needed;
        for (int c = 0; c < 3; ++c) {
            needed.push_back(sample_variance_channel(c));
            for (uint32_t b = 0; b < std::max(k, 2u); ++b) needed.push_back(batch_channel(b, c));
        }
        for (const std::string& name : needed)
            if (!img.has(name))
                input_error("{}: {} is '{}' but the file has no channel {}, which merge needs "
                            "(render --sampler sobol --film full writes it)",
                            path, h::kVarianceEstimator, estimator, name);
    }
    const std::string where = fmt::format("{}: {}", path, h::kSampleRanges);
    const std::vector<SampleRange> ranges =
        parse_sample_ranges(text_field(path, img, h::kSampleRanges), where);
    uint64_t n = 0;
    for (const SampleRange& r : ranges) n += r.end - r.begin;
    if (int_field(path, img, h::kSpp) != int64_t(n))
        input_error("{}: {} is {}, but {} '{}' holds {} samples", path, h::kSpp,
                    img.integers.at(h::kSpp), h::kSampleRanges, img.strings.at(h::kSampleRanges),
                    n);

    if (n_ == 0) {
        first_path_ = path;
        first_.width = img.width;
        first_.height = img.height;
        first_.strings = img.strings;
        for (const auto& [name, data] : img.channels)
            if (is_id(name)) first_.channels[name] = data;
    } else {
        const std::string& first = first_path_;
        if (img.width != first_.width || img.height != first_.height)
            input_error("{}: {}x{} pixels, but {} has {}x{}", path, img.width, img.height, first,
                        first_.width, first_.height);
        for (const char* key : kSame)
            if (img.strings.at(key) != first_.strings.at(key))
                input_error("{}: {} is '{}', but {} has '{}': parts of one merge must render the "
                            "same scene, camera, settings, backend and variance estimator",
                            path, key, img.strings.at(key), first, first_.strings.at(key));
        if (k != batch_count_.size())
            input_error("{}: {} batches, but {} has {}", path, k, first, batch_count_.size());
        for (const auto& [name, c] : channels_)
            if (!img.has(name)) input_error("{}: no channel {}, which {} has", path, name, first);
        for (const auto& [name, data] : img.channels)
            if (!channels_.count(name) && !is_id(name) && !is_moment(name))
                input_error("{}: channel {}, which {} does not have", path, name, first);
    }
    for (const SampleRange& r : ranges)
        for (const Range& o : ranges_)
            if (o.seed == r.seed && o.begin < r.end && r.begin < o.end)
                input_error("{}: samples {}-{} of seed {} overlap samples {}-{} of {} ({}); "
                            "parts must render disjoint ranges, or different seeds",
                            path, r.begin, r.end, r.seed, o.begin, o.end, o.path, h::kSampleRanges);

    const size_t pixels = size_t(img.width) * size_t(img.height);
    const double na = double(n_), nb = double(n);
    std::vector<uint64_t> part_batch(k, 0); // the part's samples per pixel in each batch
    for (uint32_t b = 0; b < k; ++b)
        for (const SampleRange& r : ranges) part_batch[b] += batch_samples(r.begin, r.end, b, k);
    if (n_ == 0) batch_count_.assign(k, 0);
    for (const auto& [name, data] : img.channels) {
        if (is_id(name) || is_moment(name)) continue;
        Channel& c = channels_[name];
        const std::string var_name = "variance." + name;
        if (!img.has(var_name)) {
            c.sum.resize(pixels, 0.0);
            for (size_t i = 0; i < pixels; ++i) c.sum[i] += nb * double(data[i]);
            continue;
        }
        // The M2 of the part's samples: from its variance of the mean n (n - 1) v, or from
        // its sample variance (n - 1) s^2.
        const int colour = colour_index(name);
        const bool from_samples = batch_part && colour >= 0;
        const std::vector<float>& var =
            img.channel(from_samples ? sample_variance_channel(colour) : var_name);
        const double m2_scale = from_samples ? nb - 1.0 : nb * (nb - 1.0);
        c.mean.resize(pixels, 0.0);
        c.m2.resize(pixels, 0.0);
        for (size_t i = 0; i < pixels; ++i)
            merge_moments(na, c.mean[i], c.m2[i], nb, double(data[i]), double(var[i]) * m2_scale);
        if (!from_samples) continue;
        c.batch_sum.resize(pixels * k, 0.0);
        for (uint32_t b = 0; b < k; ++b) {
            const std::vector<float>& mean_b = img.channel(batch_channel(b, colour));
            for (size_t i = 0; i < pixels; ++i)
                c.batch_sum[i * k + b] += double(part_batch[b]) * double(mean_b[i]);
        }
    }
    for (uint32_t b = 0; b < k; ++b) batch_count_[b] += part_batch[b];
    estimator_ = estimator;
    for (const SampleRange& r : ranges) ranges_.push_back({r.seed, r.begin, r.end, path});
    const auto device = img.strings.find(h::kDevice);
    const std::string device_name = device == img.strings.end() ? "" : device->second;
    if (std::find(devices_.begin(), devices_.end(), device_name) == devices_.end())
        devices_.push_back(device_name);
    const auto time = img.reals.find(h::kRenderTime);
    const double seconds = time == img.reals.end() ? 0.0 : time->second;
    render_time_s_ += seconds;
    part_lines_.push_back(fmt::format("{}: samples {}, {} spp, {} on {}, {:.3f} s", path,
                                      img.strings.at(h::kSampleRanges), n,
                                      img.strings.at(h::kBackend), device_name, seconds));
    n_ += n;
}

ExrImage RenderMerger::result(FilmLayout layout) const {
    if (n_ == 0) input_error("merge: no parts");
    ExrImage out = first_;
    out.strings[h::kFilm] = film_layout_name(layout);
    const double N = double(n_);
    const uint32_t k = uint32_t(batch_count_.size());
    auto plane = [&](const std::string& name, size_t pixels) -> std::vector<float>& {
        std::vector<float>& v = out.channels[name];
        v.resize(pixels);
        return v;
    };
    for (const auto& [name, c] : channels_) {
        if (c.mean.empty()) {
            std::vector<float>& data = plane(name, c.sum.size());
            for (size_t i = 0; i < data.size(); ++i) data[i] = float(c.sum[i] / N);
            continue;
        }
        const size_t pixels = c.mean.size();
        std::vector<float>& data = plane(name, pixels);
        std::vector<float>& var = plane("variance." + name, pixels);
        for (size_t i = 0; i < pixels; ++i) data[i] = float(c.mean[i]);
        if (c.batch_sum.empty()) {
            for (size_t i = 0; i < pixels; ++i)
                var[i] = float(N > 1 ? c.m2[i] / ((N - 1.0) * N) : 0.0);
            continue;
        }
        const int colour = colour_index(name);
        std::vector<float>& s2 = plane(sample_variance_channel(colour), pixels);
        std::vector<BatchSum<double>> batch(k);
        for (size_t i = 0; i < pixels; ++i) {
            const double v = N > 1 ? c.m2[i] / (N - 1.0) : 0.0;
            s2[i] = layout == FilmLayout::full ? float(v) : lean_sample_variance(v);
            for (uint32_t b = 0; b < k; ++b) batch[b] = {c.batch_sum[i * k + b], batch_count_[b]};
            var[i] = float(batch_variance_of_mean(batch.data(), k));
        }
        if (layout == FilmLayout::lean) continue;
        for (uint32_t b = 0; b < k; ++b) {
            std::vector<float>& mean_b = plane(batch_channel(b, colour), pixels);
            for (size_t i = 0; i < pixels; ++i)
                mean_b[i] = batch_count_[b] > 0
                                ? float(c.batch_sum[i * k + b] / double(batch_count_[b]))
                                : 0.0f;
        }
    }
    if (batches()) {
        std::vector<BatchSum<double>> batch(k);
        for (uint32_t b = 0; b < k; ++b) batch[b].count = batch_count_[b];
        if (const uint32_t filled = filled_batches(batch.data(), k); filled > 1)
            out.integers[h::kVarianceDof] = int64_t(filled - 1);
    }
    std::vector<SampleRange> ranges;
    for (const Range& r : ranges_) ranges.push_back({r.seed, r.begin, r.end});
    out.strings[h::kSampleRanges] = format_sample_ranges(ranges);
    out.integers[h::kSpp] = int64_t(n_);
    const bool one_seed = std::all_of(ranges.begin(), ranges.end(), [&](const SampleRange& r) {
        return r.seed == ranges.front().seed;
    });
    if (one_seed) out.integers[h::kSeed] = int64_t(ranges.front().seed);
    std::string devices, parts;
    for (const std::string& d : devices_) devices += (devices.empty() ? "" : "; ") + d;
    for (const std::string& p : part_lines_) parts += p + "\n";
    out.strings[h::kDevice] = devices;
    out.strings[h::kParts] = parts;
    out.reals[h::kRenderTime] = render_time_s_;
    return out;
}

ExrImage merge_files(const std::vector<std::string>& paths, FilmLayout layout) {
    RenderMerger merger;
    for (const std::string& p : paths) merger.add(p, read_exr(p));
    return merger.result(layout);
}

} // namespace tp
