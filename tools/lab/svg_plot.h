// A line plot as SVG, written by hand (no plotting dependency): one <polyline> per series over a
// logarithmic x axis and a logarithmic (decades) or linear y axis, grid lines, a legend, and
// dashed horizontal guides at chosen y values.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace tp::lab {

struct PlotSeries {
    std::string label;
    std::vector<std::pair<double, double>> points; // (x, y); non-positive x (or y on a log
                                                   // axis) are left out
};

struct LinePlot {
    std::string title, x_label, y_label;
    std::vector<PlotSeries> series;
    std::vector<double> guides; // horizontal dashed lines (y values), labelled
    // y from 0 on a linear scale instead of decades: rates, whose ratios read off the height.
    bool linear_y = false;
    // Labelled x positions (say the image sizes of a sweep), drawn instead of the decade labels.
    std::vector<std::pair<double, std::string>> x_ticks;
    bool markers = false; // a dot at every point, for sparse series
};

std::string svg_line_plot(const LinePlot& plot);

} // namespace tp::lab
