// The machine-readable outputs of a benchmark, all derived from its JSON result (the one
// record of the run, bench/run_sections.h): CSV tables and one SVG plot per scene.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace tp::lab {

// ladder.csv, table.csv, peer.csv and sizes.csv in `dir`, for the sections the result has.
void write_csv_files(const nlohmann::json& result, const std::string& dir);

// plots/<scene>.svg in `dir`: relMSE (excess over the reference noise) against wall time,
// log-log, one line per backend and mode, guides at 1e-2 and 1e-3. Records each plot's path,
// relative to `dir`, as scenes[i].plot. And plots/sizes/<scene>.svg: Mrays/s against image size
// (sizes_report.h), recorded as scenes[i].sizes_plot.
void write_plots(nlohmann::json& result, const std::string& dir);

} // namespace tp::lab
