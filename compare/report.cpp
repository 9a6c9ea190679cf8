#include "compare/report.h"

#include "compare/colormap.h"
#include "compare/display.h"
#include "compare/distributions.h"
#include "compare/significance_map.h"
#include "image/png_io.h"
#include "util/error.h"
#include "util/markup_escape.h"
#include "util/output_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace tp {
namespace {

const char* const kChannel[3] = {"R", "G", "B"};

double percentile_abs(std::vector<double> v, double q) {
    for (double& x : v) x = std::fabs(x);
    const size_t k = std::min(v.size() - 1, size_t(q * double(v.size())));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
}

void put(std::vector<uint8_t>& rgb, size_t i, std::array<uint8_t, 3> c) {
    std::copy(c.begin(), c.end(), rgb.begin() + std::ptrdiff_t(3 * i));
}

struct Figure {
    std::string file, title, caption;
};

std::string numbers_table(const CompareResult& r) {
    std::string rows;
    auto row = [&](const std::string& k, const std::string& v) {
        rows += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", k, v);
    };
    const size_t m = r.local.holm.rejected.size();
    row("verdict", fmt::format("<b>{}</b> (p = {:.3g}, alpha = {})",
                               r.different ? "different" : "consistent", r.p_value, r.alpha));
    row("mode", r.mode == CompareMode::TwoSample
                    ? "two-sample: local at alpha/2 + global at alpha/2 (Bonferroni)"
                    : "reference (one image exact): global test at alpha; local advisory");
    row("local test",
        fmt::format("Welch t per pixel-channel, Holm: {} of {} significant ({:.3g}%), {} pixels; "
                    "p = {:.3g}; max |z| = {:.2f} at ({}, {}) {}",
                    r.local.holm.count, m, 100.0 * double(r.local.holm.count) / double(m),
                    r.local.significant_pixels, r.local.holm.p_value, r.local.max_abs_z,
                    r.local.max_x, r.local.max_y, kChannel[r.local.max_channel]));
    row("global test",
        fmt::format(
            "chi-square over {} tiles of {}x{} and 3 channels: X = {:.1f}, scaled by {:.2f} "
            "for the channels' correlation (RG {:.2f}, RB {:.2f}, GB {:.2f}), {:.1f} dof: "
            "p = {:.3g}. Per channel: R {:.1f}, G {:.1f}, B {:.1f} on {} dof",
            r.global.tiles(), r.global.tile, r.global.tile, r.global.statistic, r.global.scale,
            r.global.correlation[0], r.global.correlation[1], r.global.correlation[2], r.global.dof,
            r.global.p_value, r.global.chi2[0], r.global.chi2[1], r.global.chi2[2],
            r.global.tiles()));
    if (r.diff.rule.borrower != VarianceRule::None) row("unequal spp", borrowing_sentence(r.diff));
    row("zero-variance floor",
        fmt::format("relative {}; {} pixel-channels had no variance in either image",
                    r.floor_relative, r.diff.at_floor));
    std::string metrics = "<table class=\"m\"><tr><th></th><th>R</th><th>G</th><th>B</th>"
                          "<th>all</th></tr>\n";
    auto mrow = [&](const char* name, double ChannelMetrics::*f, bool all) {
        metrics += fmt::format("<tr><th>{}</th>", name);
        for (const ChannelMetrics& c : r.metrics.channel)
            metrics += fmt::format("<td>{:.4g}</td>", c.*f);
        metrics +=
            all ? fmt::format("<td>{:.4g}</td></tr>\n", r.metrics.all.*f) : "<td></td></tr>\n";
    };
    mrow("MSE", &ChannelMetrics::mse, true);
    mrow("MSE expected from noise", &ChannelMetrics::mse_noise, true);
    mrow("relMSE", &ChannelMetrics::relmse, true);
    mrow("MAPE", &ChannelMetrics::mape, true);
    mrow("bias (A - B)", &ChannelMetrics::bias, true);
    mrow("bias std. error", &ChannelMetrics::bias_stderr, false);
    metrics += "</table>";
    row("error metrics", metrics);
    row("PSNR (sRGB display)", !r.psnr ? "not available (built without OpenImageIO)"
                               : std::isfinite(*r.psnr) ? fmt::format("{:.2f} dB", *r.psnr)
                                                        : "inf (identical)");
    return rows;
}

} // namespace

void write_report(const std::string& dir, const CompareResult& r, const RgbImage& a,
                  const RgbImage& b) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) runtime_error("cannot create report directory {}: {}", dir, ec.message());
    const int w = r.diff.width, h = r.diff.height;
    const size_t n = size_t(w) * size_t(h);
    const std::string base = dir + "/";

    write_png(base + "a.png", w, h, display_srgb8(a, r.exposure));
    write_png(base + "b.png", w, h, display_srgb8(b, r.exposure));

    std::vector<double> mean_d(n);
    for (size_t i = 0; i < n; ++i)
        mean_d[i] = (r.diff.d[0][i] + r.diff.d[1][i] + r.diff.d[2][i]) / 3.0;
    double d_scale = percentile_abs(mean_d, 0.99);
    if (!(d_scale > 0.0)) d_scale = 1.0;
    std::vector<uint8_t> rgb(3 * n);
    for (size_t i = 0; i < n; ++i) put(rgb, i, diverging_color(mean_d[i] / d_scale));
    write_png(base + "difference.png", w, h, rgb);

    write_png(base + "z.png", w, h, significance_map(r));
    const double z_full = significance_full_z(r);

    // Tile z at full colour where a single tile would be significant by Bonferroni over the
    // 3 K tile-channels, the same rule as for pixels (the chi-square has no per-tile threshold).
    const double tile_full =
        normal_upper_quantile(r.global_level / (2.0 * 3.0 * double(r.global.tiles())));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t j =
                size_t(y / r.global.tile) * size_t(r.global.tiles_x) + size_t(x / r.global.tile);
            const double z = signed_max(r.global.z[0][j], r.global.z[1][j], r.global.z[2][j]);
            put(rgb, size_t(y) * size_t(w) + size_t(x), diverging_color(z / tile_full));
        }
    write_png(base + "tiles.png", w, h, rgb);

    std::vector<Figure> figures = {
        {"a.png", "A", markup_escape(a.path)},
        {"b.png", "B", markup_escape(b.path)},
        {"difference.png", "A &minus; B",
         fmt::format("mean over R, G, B; full colour at &plusmn;{:.3g}", d_scale)},
        {"z.png", "per-pixel z",
         fmt::format("channel of largest |z|; full colour at |z| = {:.2f}; yellow: significant "
                     "after Holm{}",
                     z_full,
                     r.local_in_verdict() ? ""
                                          : " (advisory: one-sample t, not calibrated for "
                                            "skewed pixels)")},
        {"tiles.png", fmt::format("tile z ({}&times;{})", r.global.tile, r.global.tile),
         fmt::format("channel of largest |z|; full colour at |z| = {:.2f}", tile_full)},
    };
    if (r.diff.rule.borrower != VarianceRule::None) {
        // Orange where the image with fewer samples took the other's per-sample variance.
        for (size_t i = 0; i < n; ++i)
            put(rgb, i,
                r.diff.borrowed[i] ? std::array<uint8_t, 3>{240, 140, 0}
                                   : std::array<uint8_t, 3>{60, 60, 60});
        write_png(base + "variance.png", w, h, rgb);
        figures.push_back({"variance.png", "variance borrowed", borrowing_sentence(r.diff)});
    }
    std::string figs;
    for (const Figure& f : figures)
        figs += fmt::format("<figure><img src=\"{}\" alt=\"{}\"><figcaption><b>{}</b><br>{}"
                            "</figcaption></figure>\n",
                            f.file, f.file, f.title, f.caption);

    const std::string html = fmt::format(
        R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>twinpath compare</title>
<style>
body {{ font-family: sans-serif; margin: 1em; }}
.figs {{ display: flex; flex-wrap: wrap; gap: 12px; }}
figure {{ margin: 0; width: 256px; }}
img {{ width: 256px; image-rendering: pixelated; border: 1px solid #888; }}
figcaption {{ font-size: small; word-break: break-all; }}
table {{ border-collapse: collapse; margin-top: 1em; }}
th, td {{ border: 1px solid #ccc; padding: 3px 6px; text-align: left; vertical-align: top; }}
.legend {{ width: 256px; height: 12px; background: linear-gradient(to right,
  rgb(59,76,192), rgb(221,221,221), rgb(180,4,38)); }}
</style></head>
<body data-images-loaded="pending">
<h1>twinpath compare: {verdict}</h1>
<div class="figs">
{figs}</div>
<div class="legend"></div><div>blue: A below B &nbsp; grey: equal &nbsp; red: A above B</div>
<table>
{rows}</table>
<script>
window.addEventListener('load', function () {{
  var images = document.querySelectorAll('img'), ok = 0;
  images.forEach(function (img) {{
    var loaded = img.complete && img.naturalWidth > 0;
    img.setAttribute('data-loaded', loaded ? 'yes' : 'no');
    if (loaded) ok++;
  }});
  document.body.setAttribute('data-images-loaded', ok + '/' + images.length);
}});
</script>
</body></html>
)",
        fmt::arg("verdict", r.different ? "different" : "consistent"), fmt::arg("figs", figs),
        fmt::arg("rows", numbers_table(r)));
    write_output_file(base + "index.html", html);
}

} // namespace tp
