#include "compare/rgb_image.h"

#include "image/exr_io.h"
#include "render/film.h"
#include "render/render_header.h"
#include "util/error.h"

#include <array>
#include <cmath>
#include <fmt/format.h>

namespace tp {
namespace {

const char* const kColour[3] = {"R", "G", "B"};
const std::array<std::string, 3> kVariance = {"variance.R", "variance.G", "variance.B"};
const std::array<std::string, 3> kSampleVariance = {
    sample_variance_channel(0), sample_variance_channel(1), sample_variance_channel(2)};

std::string channel_list(const ExrImage& img) {
    std::string s;
    for (const auto& [name, data] : img.channels) s += (s.empty() ? "" : ", ") + name;
    return s.empty() ? "none" : s;
}

// Counts the non-finite values of every channel the statistics read; never drops them.
void require_finite(const std::string& path, const ExrImage& img,
                    const std::vector<std::string>& names) {
    std::string detail;
    size_t total = 0, first = SIZE_MAX;
    std::vector<bool> bad_pixel(size_t(img.width) * size_t(img.height), false);
    for (const std::string& name : names) {
        const std::vector<float>& data = img.channel(name);
        size_t count = 0;
        for (size_t i = 0; i < data.size(); ++i)
            if (!std::isfinite(data[i])) {
                ++count;
                bad_pixel[i] = true;
                first = std::min(first, i);
            }
        if (count) detail += fmt::format("{}{} {}", detail.empty() ? "" : ", ", name, count);
        total += count;
    }
    if (total == 0) return;
    size_t pixels = 0;
    for (bool b : bad_pixel) pixels += b;
    input_error("{}: {} NaN/Inf values in {} pixels ({}); first at pixel ({}, {})", path, total,
                pixels, detail, first % size_t(img.width), first / size_t(img.width));
}

} // namespace

RgbImage load_rgb_image(const std::string& path) {
    return rgb_image_from_exr(read_exr(path), path);
}

RgbImage rgb_image_from_exr(const ExrImage& img, const std::string& path) {
    for (const char* c : kColour)
        if (!img.has(c))
            input_error("{}: no channel {} (channels: {})", path, c, channel_list(img));
    auto count_of = [&](const std::array<std::string, 3>& set) {
        const int n = img.has(set[0]) + img.has(set[1]) + img.has(set[2]);
        if (n != 0 && n != 3)
            input_error("{}: has only some of {}, {}, {} (channels: {})", path, set[0], set[1],
                        set[2], channel_list(img));
        return n;
    };
    const int nvar = count_of(kVariance), nsample = count_of(kSampleVariance);

    std::vector<std::string> names(kColour, kColour + 3);
    if (nvar == 3) names.insert(names.end(), kVariance.begin(), kVariance.end());
    if (nsample == 3) names.insert(names.end(), kSampleVariance.begin(), kSampleVariance.end());
    require_finite(path, img, names);
    auto read_variance = [&](const std::string& name, std::vector<double>& out) {
        const std::vector<float>& v = img.channel(name);
        for (size_t i = 0; i < v.size(); ++i)
            if (v[i] < 0.0f)
                input_error("{}: negative variance {} in {} at pixel ({}, {})", path, v[i], name,
                            i % size_t(img.width), i / size_t(img.width));
        out.assign(v.begin(), v.end());
    };

    RgbImage out;
    out.path = path;
    out.width = img.width;
    out.height = img.height;
    for (int c = 0; c < 3; ++c) {
        const std::vector<float>& m = img.channel(kColour[c]);
        out.mean[size_t(c)].assign(m.begin(), m.end());
        if (nvar == 3) read_variance(kVariance[c], out.var[size_t(c)]);
        if (nsample == 3) read_variance(kSampleVariance[c], out.sample_var[size_t(c)]);
    }
    if (auto it = img.integers.find("twinpath:spp"); it != img.integers.end()) {
        if (it->second < 1) input_error("{}: twinpath:spp is {}, expected >= 1", path, it->second);
        out.spp = it->second;
    }
    if (auto it = img.integers.find("twinpath:variance_dof"); it != img.integers.end()) {
        if (it->second < 1)
            input_error("{}: twinpath:variance_dof is {}, expected >= 1", path, it->second);
        out.variance_dof = it->second;
    }
    if (auto it = img.strings.find(header::kSampleRanges); it != img.strings.end()) {
        try {
            out.sample_ranges = parse_sample_ranges(it->second, path);
        } catch (const InputError&) {
            out.sample_ranges.clear();
        }
    }
    if (auto it = img.strings.find(header::kSampler); it != img.strings.end())
        out.sampler = it->second;
    return out;
}

void require_same_size(const RgbImage& a, const RgbImage& b) {
    if (a.width != b.width || a.height != b.height)
        input_error("{} is {}x{} but {} is {}x{}: images of different sizes cannot be compared",
                    a.path, a.width, a.height, b.path, b.width, b.height);
}

} // namespace tp
