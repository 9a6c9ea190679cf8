#include "tools/lab/svg_plot.h"

#include "util/markup_escape.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tp::lab {
namespace {

constexpr double kWidth = 760, kHeight = 460;
constexpr double kLeft = 80, kRight = 230, kTop = 40, kBottom = 60;
// Rotated x tick labels (x_ticks) need more room below the plot.
constexpr double kBottomTicks = 100;
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

// A linear axis [0, top] with ticks every `step`, step a 1, 2 or 5 times a power of ten that
// gives at most five intervals (at least one) over the largest value.
struct LinearAxis {
    double top = 1, step = 0.2;
};

LinearAxis linear_axis_of(const std::vector<double>& values) {
    double mx = 0;
    for (double v : values)
        if (std::isfinite(v)) mx = std::max(mx, v);
    if (!(mx > 0)) return {};
    const double raw = mx / 5, decade = std::pow(10.0, std::floor(std::log10(raw)));
    double step = 10 * decade;
    for (double m : {1.0, 2.0, 5.0})
        if (m * decade >= raw) {
            step = m * decade;
            break;
        }
    return {std::ceil(mx / step) * step, step};
}

} // namespace

std::string svg_line_plot(const LinePlot& plot) {
    std::vector<double> xs, ys = plot.guides;
    for (const PlotSeries& s : plot.series)
        for (const auto& [x, y] : s.points) {
            xs.push_back(x);
            ys.push_back(y);
        }
    for (const auto& tick : plot.x_ticks) xs.push_back(tick.first);
    const Decades dx = decades_of(xs), dy = decades_of(ys);
    // log10 x across the plot: whole decades, or the labelled ticks' span and a little more.
    double x_lo = dx.lo, x_hi = dx.hi;
    if (!plot.x_ticks.empty()) {
        x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
        for (const auto& tick : plot.x_ticks)
            if (tick.first > 0) {
                x_lo = std::min(x_lo, std::log10(tick.first) - 0.15);
                x_hi = std::max(x_hi, std::log10(tick.first) + 0.15);
            }
    }
    const LinearAxis ly = linear_axis_of(ys);
    const double bottom = plot.x_ticks.empty() ? kBottom : kBottomTicks;
    const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - bottom;
    const auto X = [&](double x) { return kLeft + (std::log10(x) - x_lo) / (x_hi - x_lo) * pw; };
    const auto Y = [&](double y) {
        return plot.linear_y ? kTop + (1 - y / ly.top) * ph
                             : kTop + (dy.hi - std::log10(y)) / (dy.hi - dy.lo) * ph;
    };
    const auto drawable = [&](double x, double y) {
        return x > 0 && std::isfinite(x) && std::isfinite(y) && (plot.linear_y ? y >= 0 : y > 0);
    };

    std::string svg =
        fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
                    "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\" font-size=\"12\">\n"
                    "<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n"
                    "<text x=\"{2}\" y=\"24\" font-size=\"15\">{3}</text>\n",
                    kWidth, kHeight, kLeft, markup_escape(plot.title));
    const auto x_grid = [&](double x) {
        return fmt::format("<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" "
                           "stroke=\"#ddd\"/>\n",
                           X(x), kTop, kTop + ph);
    };
    if (plot.x_ticks.empty()) {
        for (int k = dx.lo; k <= dx.hi; ++k)
            svg +=
                x_grid(std::pow(10.0, k)) +
                fmt::format("<text x=\"{0:.1f}\" y=\"{1}\" text-anchor=\"middle\">1e{2}</text>\n",
                            X(std::pow(10.0, k)), kTop + ph + 18, k);
    } else {
        for (const auto& [x, label] : plot.x_ticks)
            if (x > 0)
                svg += x_grid(x) + fmt::format("<text transform=\"translate({:.1f} {}) "
                                               "rotate(-40)\" text-anchor=\"end\">{}</text>\n",
                                               X(x) + 4, kTop + ph + 14, markup_escape(label));
    }
    const auto y_grid = [&](double y, const std::string& label) {
        return fmt::format("<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" "
                           "stroke=\"#ddd\"/>\n<text x=\"{3}\" y=\"{4:.1f}\" "
                           "text-anchor=\"end\">{5}</text>\n",
                           kLeft, Y(y), kLeft + pw, kLeft - 6, Y(y) + 4, label);
    };
    if (plot.linear_y) {
        const int n = int(std::lround(ly.top / ly.step));
        for (int k = 0; k <= n; ++k) svg += y_grid(k * ly.step, fmt::format("{:g}", k * ly.step));
    } else {
        for (int k = dy.lo; k <= dy.hi; ++k)
            svg += y_grid(std::pow(10.0, k), fmt::format("1e{}", k));
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
        if (!drawable(1, g)) continue;
        svg += fmt::format("<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" "
                           "stroke=\"#888\" stroke-dasharray=\"6 4\"/>\n<text x=\"{3}\" "
                           "y=\"{4:.1f}\" fill=\"#666\">{5:g}</text>\n",
                           kLeft, Y(g), kLeft + pw, kLeft + pw + 4, Y(g) + 4, g);
    }
    for (size_t i = 0; i < plot.series.size(); ++i) {
        const PlotSeries& s = plot.series[i];
        const char* color = kColors[i % (sizeof kColors / sizeof *kColors)];
        std::string pts, dots;
        for (const auto& [x, y] : s.points)
            if (drawable(x, y)) {
                pts += fmt::format("{:.1f},{:.1f} ", X(x), Y(y));
                if (plot.markers)
                    dots +=
                        fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" fill=\"{}\"/>\n",
                                    X(x), Y(y), color);
            }
        svg += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\" "
                           "points=\"{}\"><title>{}</title></polyline>\n",
                           color, pts, markup_escape(s.label));
        svg += dots;
        // The legend leaves room on the left for the guides' labels when there are guides.
        const double legend_x = kLeft + pw + (plot.guides.empty() ? 12 : 40);
        const double legend_y = kTop + 14 + 20 * double(i);
        svg += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"{3}\" "
                           "stroke-width=\"2\"/>\n<text x=\"{4}\" y=\"{5}\">{6}</text>\n",
                           legend_x, legend_y, legend_x + 24, color, legend_x + 30, legend_y + 4,
                           markup_escape(s.label));
    }
    svg += "</svg>\n";
    return svg;
}

} // namespace tp::lab
