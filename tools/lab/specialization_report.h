// The report of a `twinpath bench --specialization` result (bench/specialization.h).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace tp::lab {

// The markdown of the section: one row per scene and backend/mode, with the driver's register
// counts of both variants where it reported them (--pipeline-stats).
std::string specialization_section(const nlohmann::json& result);

} // namespace tp::lab
