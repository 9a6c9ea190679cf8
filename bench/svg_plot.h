// A log-log line plot as SVG, written by hand (no plotting dependency): one <polyline> per
// series, decade grid lines, a legend, and dashed horizontal guides at chosen y values.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace tp::bench {

struct PlotSeries {
    std::string label;
    std::vector<std::pair<double, double>> points; // (x, y); non-positive values are left out
};

struct LogLogPlot {
    std::string title, x_label, y_label;
    std::vector<PlotSeries> series;
    std::vector<double> guides; // horizontal dashed lines (y values), labelled
};

std::string svg_loglog(const LogLogPlot& plot);

} // namespace tp::bench
