#include "compare/merge.h"

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

bool is_id(const std::string& channel) {
    return channel.rfind("id.", 0) == 0;
}

} // namespace

void RenderMerger::add(const std::string& path, const ExrImage& img) {
    // Fields every part must have, and must have equal to the first part's.
    static const char* const kSame[] = {h::kSceneHash, h::kCamera, h::kSettings, h::kBackend};
    const std::string& estimator = text_field(path, img, h::kVarianceEstimator);
    if (estimator != kVarianceFromSamples)
        input_error("{}: {} is '{}'; merge combines variances estimated from '{}' only", path,
                    h::kVarianceEstimator, estimator, kVarianceFromSamples);
    for (const char* key : kSame) text_field(path, img, key);
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
                            "same scene, camera, settings and backend",
                            path, key, img.strings.at(key), first, first_.strings.at(key));
        for (const auto& [name, c] : channels_)
            if (!img.has(name)) input_error("{}: no channel {}, which {} has", path, name, first);
        for (const auto& [name, data] : img.channels)
            if (!channels_.count(name) && !is_id(name))
                input_error("{}: channel {}, which {} does not have", path, name, first);
    }
    for (const SampleRange& r : ranges)
        for (const Range& o : ranges_)
            if (o.seed == r.seed && o.begin < r.end && r.begin < o.end)
                input_error("{}: samples {}-{} of seed {} overlap samples {}-{} of {} ({}); "
                            "parts must render disjoint ranges, or different seeds",
                            path, r.begin, r.end, r.seed, o.begin, o.end, o.path, h::kSampleRanges);

    const size_t pixels = size_t(img.width) * size_t(img.height);
    const double na = double(n_), nb = double(n), total = na + nb;
    for (const auto& [name, data] : img.channels) {
        if (is_id(name) || name.rfind("variance.", 0) == 0) continue;
        Channel& c = channels_[name];
        c.sum.resize(pixels, 0.0);
        const std::string var_name = "variance." + name;
        if (!img.has(var_name)) {
            for (size_t i = 0; i < pixels; ++i) c.sum[i] += nb * double(data[i]);
            continue;
        }
        const std::vector<float>& var = img.channel(var_name);
        Channel& v = channels_[var_name];
        v.m2.resize(pixels, 0.0);
        for (size_t i = 0; i < pixels; ++i) {
            const double mb = data[i];
            const double d = n_ > 0 ? mb - c.sum[i] / na : 0.0;
            v.m2[i] += double(var[i]) * nb * (nb - 1.0) + d * d * na * nb / total;
            c.sum[i] += nb * mb;
        }
    }
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

ExrImage RenderMerger::result() const {
    if (n_ == 0) input_error("merge: no parts");
    ExrImage out = first_;
    const double N = double(n_);
    for (const auto& [name, c] : channels_) {
        std::vector<float>& data = out.channels[name];
        const bool variance = !c.m2.empty();
        data.resize(variance ? c.m2.size() : c.sum.size());
        for (size_t i = 0; i < data.size(); ++i)
            data[i] =
                variance ? float(N > 1 ? c.m2[i] / ((N - 1.0) * N) : 0.0) : float(c.sum[i] / N);
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

ExrImage merge_files(const std::vector<std::string>& paths) {
    RenderMerger merger;
    for (const std::string& p : paths) merger.add(p, read_exr(p));
    return merger.result();
}

} // namespace tp
