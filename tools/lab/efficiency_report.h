// The report of the time-to-error comparison next to a production renderer
// (peer_efficiency.h): a table per scene of spp, time, relMSE and efficiency, twinpath's over
// the peer's at the same thread count.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace tp::lab {

// The markdown of every scene's "efficiency" record in a bench result (bench.json), "" if none.
std::string efficiency_markdown(const nlohmann::json& result);

} // namespace tp::lab
