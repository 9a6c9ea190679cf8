// `twinpath verify --report DIR` (docs/debugging.md, "verify"): what verify rendered and found,
// and every command that redoes a step by hand.
//
//   DIR/<engine>.exr, DIR/pilot-<engine>.exr     the images compared and the pilots
//   DIR/<a>_vs_<b>/                               per pair: compare's report (index.html, z.png:
//                                                 the significance map, ...) and compare.json;
//                                                 with a triage also the AOV EXRs, aov.json, the
//                                                 path logs and pathdiff.txt (every logged
//                                                 pixel's pathdiff table)
//   DIR/commands.sh                               each step as twinpath commands, which rewrite
//                                                 these files with the same pixels
//   DIR/verify.json                               the plan, the timings, the verdicts, the triage
#pragma once

#include "verify/verify.h"

#include <string>

namespace tp {

struct ReportContext {
    std::string command_line; // the verify command as run, for the headers
    std::string twinpath;     // the executable that commands.sh runs by default
};

void write_verify_report(const std::string& dir, const VerifyResult& v, const ReportContext& ctx);

// The report's file name of an engine's image: "cpu", "vulkan-compute".
std::string engine_file_name(const std::string& label);

} // namespace tp
