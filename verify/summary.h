// The lines verify prints for each step (docs/debugging.md, "verify"), for the command line and
// the viewer's overlay alike.
#pragma once

#include "verify/verify.h"

#include <string>
#include <vector>

namespace tp {

// "pilots: 16 spp each in 0.9 s; a sample of the image costs cpu 4.1 ms, vulkan compute 9.8 ms
// (set-up 0.02 s, 0.61 s)"
std::string pilot_line(const VerifyResult& v);
// The spp chosen, why, and what they can find.
std::vector<std::string> plan_lines(const VerifyResult& v);
// "images at once: cpu 412 spp in 3.2 s, vulkan compute 260 spp in 3.6 s; 3.7 s wall"
std::string images_line(const VerifyResult& v);
// compare's verdict line (prefixed with the pair when there are several) and, when consistent,
// the least bias it would have found.
std::vector<std::string> verdict_lines(const VerifyResult& v, const PairVerdict& pv);
// The triage: geometry or shading, the pixels, each pixel's pathdiff, the first divergence.
std::vector<std::string> triage_lines(const VerifyResult& v, const PairVerdict& pv);
// "first divergence: field light_pdf at vertex 0 of pixel 32,48, sample 0: cpu 17.91454,
// vulkan compute 35.82907", or "" when the triage found none.
std::string divergence_line(const VerifyResult& v, const PairVerdict& pv);

// "1%", "0.25%": a relative bias as a percentage with 2 significant digits.
std::string percent(double fraction);

} // namespace tp
