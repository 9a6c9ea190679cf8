// The machine-readable result of a comparison (`--json`); docs/compare.md lists the fields.
#pragma once

#include "compare/compare.h"

#include <nlohmann/json.hpp>

namespace tp {

nlohmann::json compare_json(const CompareResult& r, const RgbImage& a, const RgbImage& b);

// The one-line verdict printed on stdout.
std::string compare_verdict_line(const CompareResult& r);

} // namespace tp
