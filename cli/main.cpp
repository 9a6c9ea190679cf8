// twinpath: one executable, subcommands render, view, verify, compare, merge, bench, pathdiff,
// info.
// Exit codes: 0 success (compare, verify: consistent), 1 compare or verify found a difference,
// 2 bad usage or bad input, 3 runtime failure (no device, out of memory, device lost).
#include "commands.h"
#include "scene/text_parse.h"
#include "util/run_command.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

#include <fmt/core.h>

#include <string>
#include <vector>

// Closes the Vulkan device that renders keep open (vulkan_renderer.h) when main returns, before
// the exit-time destructors of the driver run.
struct CloseVulkanOnReturn {
    ~CloseVulkanOnReturn() { tp::close_vulkan_device(); }
};

int main(int argc, char** argv) {
    const CloseVulkanOnReturn close_vulkan;
    CLI::App app{"twinpath: dual-backend (Embree CPU reference / Vulkan) path tracer"};
    app.require_subcommand(1);
    const std::vector<tp::Subcommand> commands = {
        tp::add_render_command(app), tp::add_compare_command(app), tp::add_merge_command(app),
        tp::add_info_command(app),   tp::add_bench_command(app),   tp::add_pathdiff_command(app),
        tp::add_view_command(app),   tp::add_verify_command(app),
    };
    // CLI11 would call an unknown first word a missing subcommand: name it and list them.
    if (argc > 1 && argv[1][0] != '-') {
        std::string names;
        bool known = false;
        for (const tp::Subcommand& c : commands) {
            names += (names.empty() ? "" : ", ") + c.app->get_name();
            known = known || c.app->get_name() == argv[1];
        }
        if (!known) {
            fmt::print(stderr,
                       "twinpath: error: '{}' is not a subcommand; the subcommands are {}\n",
                       tp::clip(argv[1]), names);
            return 2;
        }
    }
    return tp::parse_and_run(app, argc, argv, commands, "twinpath");
}
