#include "tools/lab/efficiency_report.h"

#include <fmt/format.h>

using nlohmann::json;

namespace tp::lab {

std::string efficiency_markdown(const json& r) {
    std::string md;
    for (const json& sc : r.value("scenes", json::array())) {
        if (!sc.contains("efficiency")) continue;
        const json& e = sc["efficiency"];
        if (md.empty())
            md = fmt::format(
                "\n### Time to error against a production renderer (same run)\n\nEach renderer "
                "samples for the same budget ({} s of sampling time: N times its time per spp "
                "after the first, on its own clock, which leaves out process start, scene import "
                "and BVH build) at the spp that fills it; relMSE is the excess over the "
                "reference's own noise, against a "
                "converged render of the same renderer (--ref-spp {}): twinpath's cached "
                "reference, and for a peer the mean of two independent half-spp renders. "
                "Efficiency = 1 / (relMSE x time); the last column is twinpath's over the peer's "
                "at the same thread count (> 1: twinpath reaches an error sooner).\n",
                e.value("budget_s", 0.0), e.value("ref_spp", 0));
        md += fmt::format("\n**{}**\n\n| threads | renderer | spp | time [s] | relMSE | relMSE x "
                          "time | efficiency vs peer |\n|---|---|---|---|---|---|---|\n",
                          sc.value("name", std::string()));
        for (const json& row : e["rows"]) {
            double peer_eff = 0;
            for (const json& p : e["rows"])
                if (p.value("peer", false) && p["threads"] == row["threads"] &&
                    p.contains("efficiency") && p["efficiency"].is_number())
                    peer_eff = p["efficiency"].get<double>();
            const bool ok = row.contains("relmse_excess");
            const auto num = [&](const char* key, const char* f) {
                return ok && row[key].is_number()
                           ? fmt::format(fmt::runtime(f), row[key].get<double>())
                           : std::string("–");
            };
            std::string vs = "–";
            if (row.value("peer", false))
                vs = ok ? "1" : "–";
            else if (peer_eff > 0 && row.contains("efficiency") && row["efficiency"].is_number())
                vs = fmt::format("**{:.2f}x**", row["efficiency"].get<double>() / peer_eff);
            md +=
                fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", row["threads"].get<int>(),
                            row["renderer"].get<std::string>(), row["spp"].get<int>(),
                            ok ? num("time_s", "{:.3g}")
                               : fmt::format("failed (exit {})", row["exit_code"].get<int>()),
                            num("relmse_excess", "{:.3g}"), num("relmse_times_time", "{:.3g}"), vs);
        }
        for (const json& s : e["skipped"])
            md += fmt::format("\n- peer skipped: {}\n", s.get<std::string>());
    }
    return md;
}

} // namespace tp::lab
