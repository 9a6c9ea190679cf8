// The report of a `twinpath bench --sizes` result (bench/sizes.h): each rate over the same
// backend and mode's rate at 1920x1080 (at the largest size measured when 1920x1080 is not),
// the plot of Mrays/s against image size, and the markdown section.
#pragma once

#include "bench/sizes.h"
#include "tools/lab/svg_plot.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace tp::lab {

// The size every rate is divided by: 1920x1080 when it is among `sizes`, else the largest.
bench::ImageSize ratio_base(const std::vector<bench::ImageSize>& sizes);

// Mrays/s of each point of a run over the same run's rate at `base`; null where either is
// missing.
std::vector<nlohmann::json> rate_ratios(const nlohmann::json& run, const bench::ImageSize& base);

// The plot of one scene's `sizes` runs: Mrays/s (linear) against pixels (log), one line per
// backend and mode, the sizes labelled on the x axis.
LinePlot sizes_plot(const nlohmann::json& scene);

// The markdown of the section: the summary at the run's own image size (--width x --height)
// against the ratio base, then per scene a table of Mrays/s, ratio and spp over the sizes, and
// the link to its plot (scenes[i].sizes_plot, relative to `link_base`).
std::string sizes_section(const nlohmann::json& result, const std::string& link_base);

} // namespace tp::lab
