// twinpath info [--json]: what this build can do and which devices it sees.
#include "commands.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <embree3/rtcore.h>

namespace tp {

Subcommand add_info_command(CLI::App& app) {
    auto json_out = std::make_shared<bool>(false);
    CLI::App* c =
        app.add_subcommand("info", "Show the build, the CPU backend and the Vulkan devices");
    c->add_flag("--json", *json_out, "Machine-readable output");
    return {c, [json_out] {
                nlohmann::json j;
                j["version"] = TWINPATH_VERSION;
                j["backends"]["cpu"] = {{"embree", RTC_VERSION_STRING}};
                if (*json_out)
                    fmt::print("{}\n", j.dump(2));
                else
                    fmt::print("twinpath {}\n  cpu: Embree {} + TBB\n", TWINPATH_VERSION,
                               RTC_VERSION_STRING);
                return 0;
            }};
}

} // namespace tp
