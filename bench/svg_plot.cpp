#include "bench/svg_plot.h"

#include "util/markup_escape.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tp::bench {
namespace {

constexpr double kWidth = 760, kHeight = 460;
constexpr double kLeft = 80, kRight = 230, kTop = 40, kBottom = 60;
// Distinguishable on white and for the common colour-vision deficiencies (Okabe & Ito 2008).
constexpr const char* kColors[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                   "#E69F00", "#56B4E9", "#000000", "#F0E442"};

// Whole decades [lo, hi] of log10 that cover the values (at least one decade).
struct Decades {
    int lo = 0, hi = 1;
};

Decades decades_of(const std::vector<double>& values) {
    double mn = std::numeric_limits<double>::infinity(), mx = -mn;
    for (double v : values)
        if (v > 0 && std::isfinite(v)) {
            mn = std::min(mn, v);
            mx = std::max(mx, v);
        }
    if (!std::isfinite(mn)) return {};
    Decades d{int(std::floor(std::log10(mn))), int(std::ceil(std::log10(mx)))};
    if (d.hi <= d.lo) d.hi = d.lo + 1;
    return d;
}

} // namespace

std::string svg_loglog(const LogLogPlot& plot) {
    std::vector<double> xs, ys = plot.guides;
    for (const PlotSeries& s : plot.series)
        for (const auto& [x, y] : s.points) {
            xs.push_back(x);
            ys.push_back(y);
        }
    const Decades dx = decades_of(xs), dy = decades_of(ys);
    const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
    const auto X = [&](double x) { return kLeft + (std::log10(x) - dx.lo) / (dx.hi - dx.lo) * pw; };
    const auto Y = [&](double y) { return kTop + (dy.hi - std::log10(y)) / (dy.hi - dy.lo) * ph; };

    std::string svg =
        fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
                    "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\" font-size=\"12\">\n"
                    "<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n"
                    "<text x=\"{2}\" y=\"24\" font-size=\"15\">{3}</text>\n",
                    kWidth, kHeight, kLeft, markup_escape(plot.title));
    for (int k = dx.lo; k <= dx.hi; ++k) {
        const double x = X(std::pow(10.0, k));
        svg += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" "
                           "stroke=\"#ddd\"/>\n<text x=\"{0:.1f}\" y=\"{3}\" "
                           "text-anchor=\"middle\">1e{4}</text>\n",
                           x, kTop, kTop + ph, kTop + ph + 18, k);
    }
    for (int k = dy.lo; k <= dy.hi; ++k) {
        const double y = Y(std::pow(10.0, k));
        svg += fmt::format("<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" "
                           "stroke=\"#ddd\"/>\n<text x=\"{3}\" y=\"{4:.1f}\" "
                           "text-anchor=\"end\">1e{5}</text>\n",
                           kLeft, y, kLeft + pw, kLeft - 6, y + 4, k);
    }
    svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" "
                       "stroke=\"black\"/>\n",
                       kLeft, kTop, pw, ph);
    svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", kLeft + pw / 2,
                       kHeight - 16, markup_escape(plot.x_label));
    svg += fmt::format("<text transform=\"translate(22 {}) rotate(-90)\" "
                       "text-anchor=\"middle\">{}</text>\n",
                       kTop + ph / 2, markup_escape(plot.y_label));
    for (double g : plot.guides) {
        if (!(g > 0)) continue;
        svg += fmt::format("<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" "
                           "stroke=\"#888\" stroke-dasharray=\"6 4\"/>\n<text x=\"{3}\" "
                           "y=\"{4:.1f}\" fill=\"#666\">{5:g}</text>\n",
                           kLeft, Y(g), kLeft + pw, kLeft + pw + 4, Y(g) + 4, g);
    }
    for (size_t i = 0; i < plot.series.size(); ++i) {
        const PlotSeries& s = plot.series[i];
        const char* color = kColors[i % (sizeof kColors / sizeof *kColors)];
        std::string pts;
        for (const auto& [x, y] : s.points)
            if (x > 0 && y > 0) pts += fmt::format("{:.1f},{:.1f} ", X(x), Y(y));
        svg += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\" "
                           "points=\"{}\"><title>{}</title></polyline>\n",
                           color, pts, markup_escape(s.label));
        const double ly = kTop + 14 + 20 * double(i);
        svg += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"{3}\" "
                           "stroke-width=\"2\"/>\n<text x=\"{4}\" y=\"{5}\">{6}</text>\n",
                           kLeft + pw + 40, ly, kLeft + pw + 64, color, kLeft + pw + 70, ly + 4,
                           markup_escape(s.label));
    }
    svg += "</svg>\n";
    return svg;
}

} // namespace tp::bench
