#include "compare/summary.h"

#include <fmt/format.h>

#include <cmath>

namespace tp {
namespace {

const char* const kChannel[3] = {"R", "G", "B"};

nlohmann::json per_channel(const ErrorMetrics& m, double ChannelMetrics::*field, bool all) {
    nlohmann::json j;
    for (int c = 0; c < 3; ++c) j[kChannel[c]] = m.channel[size_t(c)].*field;
    if (all) j["all"] = m.all.*field;
    return j;
}

nlohmann::json image_json(const RgbImage& img) {
    nlohmann::json j{{"path", img.path}, {"has_variance", img.has_variance()}};
    j["spp"] = img.spp ? nlohmann::json(*img.spp) : nlohmann::json(nullptr);
    return j;
}

} // namespace

nlohmann::json compare_json(const CompareResult& r, const RgbImage& a, const RgbImage& b) {
    nlohmann::json j;
    j["verdict"] = r.different ? "different" : "consistent";
    j["mode"] = r.mode == CompareMode::TwoSample ? "two-sample" : "reference";
    j["alpha"] = r.alpha;
    j["p_value"] = r.p_value;
    j["a"] = image_json(a);
    j["b"] = image_json(b);
    j["width"] = r.diff.width;
    j["height"] = r.diff.height;

    const size_t m = r.local.holm.rejected.size();
    j["local"] = {
        {"test", "Welch t per pixel-channel, Holm step-down"},
        {"in_verdict", r.local_in_verdict()},
        {"level", r.local_level},
        {"p_value", r.local.holm.p_value},
        {"pixel_channels", m},
        {"significant", r.local.holm.count},
        {"fraction_significant", double(r.local.holm.count) / double(m)},
        {"significant_pixels", r.local.significant_pixels},
        {"fraction_significant_pixels", double(r.local.significant_pixels) / double(m / 3)},
        {"max_abs_z",
         {{"z", r.local.max_abs_z},
          {"x", r.local.max_x},
          {"y", r.local.max_y},
          {"channel", kChannel[r.local.max_channel]}}},
    };
    nlohmann::json chans;
    for (int c = 0; c < 3; ++c)
        chans[kChannel[c]] = {{"chi2", r.global.chi2[size_t(c)]},
                              {"p_value", r.global.p[size_t(c)]}};
    j["global"] = {
        {"test", "chi-square of all tile-channel z^2, scaled for the channels' correlation"},
        {"level", r.global_level},
        {"p_value", r.global.p_value},
        {"tile", r.global.tile},
        {"tiles", r.global.tiles()},
        {"statistic", r.global.statistic},
        {"scale", r.global.scale},
        {"dof", r.global.dof},
        {"correlation",
         {{"RG", r.global.correlation[0]},
          {"RB", r.global.correlation[1]},
          {"GB", r.global.correlation[2]}}},
        {"channels", chans}};
    j["warnings"] = r.warnings;
    const VarianceRule& rule = r.diff.rule;
    j["variance"] = {
        {"rule", "the image with fewer samples takes the other's per-sample variance where it is "
                 "larger (docs/compare.md, unequal sample counts)"},
        {"borrower", rule.borrower == VarianceRule::A   ? nlohmann::json("a")
                     : rule.borrower == VarianceRule::B ? nlohmann::json("b")
                                                        : nlohmann::json(nullptr)},
        {"spp_ratio", rule.ratio},
        {"pixel_channels_borrowed", r.diff.variance_borrowed},
        {"pixels_borrowed", r.diff.pixels_borrowed}};
    j["floor"] = {{"relative", r.floor_relative},
                  {"pixel_channels_without_variance", r.diff.at_floor}};

    nlohmann::json& mj = j["metrics"];
    mj["reference"] = r.reference_is_a ? "a" : "b";
    mj["mse"] = per_channel(r.metrics, &ChannelMetrics::mse, true);
    mj["relmse"] = per_channel(r.metrics, &ChannelMetrics::relmse, true);
    mj["mape"] = per_channel(r.metrics, &ChannelMetrics::mape, true);
    mj["bias"] = per_channel(r.metrics, &ChannelMetrics::bias, true);
    mj["bias_stderr"] = per_channel(r.metrics, &ChannelMetrics::bias_stderr, false);
    mj["mse_noise"] = per_channel(r.metrics, &ChannelMetrics::mse_noise, true);
    mj["epsilon"] = kRelativeEpsilon;
    if (!r.psnr)
        mj["psnr_srgb_db"] = nullptr;
    else if (std::isfinite(*r.psnr))
        mj["psnr_srgb_db"] = *r.psnr;
    else
        mj["psnr_srgb_db"] = "inf";
    mj["display_exposure_stops"] = r.exposure;
    return j;
}

std::string compare_verdict_line(const CompareResult& r) {
    const size_t m = r.local.holm.rejected.size();
    return fmt::format(
        "{}: p = {:.3g} at alpha {} ({}{}; local: {} of {} pixel-channels significant, p = "
        "{:.3g}{}; global: chi-square over {} tiles of {}x{}, p = {:.3g}; relMSE {:.3g})",
        r.different ? "different" : "consistent", r.p_value, r.alpha,
        r.mode == CompareMode::TwoSample ? "two-sample" : "reference mode",
        r.diff.rule.borrower == VarianceRule::None
            ? ""
            : fmt::format(", {} spp ratio 1:{:g}, variance borrowed in {} pixel-channels",
                          r.diff.rule.borrower == VarianceRule::A ? "A:B" : "B:A",
                          r.diff.rule.ratio, r.diff.variance_borrowed),
        r.local.holm.count, m, r.local.holm.p_value, r.local_in_verdict() ? "" : ", advisory",
        r.global.tiles(), r.global.tile, r.global.tile, r.global.p_value, r.metrics.all.relmse);
}

} // namespace tp
