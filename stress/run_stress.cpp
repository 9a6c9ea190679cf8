// `twinpath bench --stress`: every stress case on every backend and mode that exists here
// (CPU/Embree; Vulkan compute; Vulkan pipeline where the device has it), at large() sizes
// (--quick: the CI sizes), then stress.md and stress.json in the output directory.
#include "stress/common.h"

#include "util/clock.h"
#include "util/error.h"
#include "util/json_file.h"
#include "util/output_file.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/renderer/vulkan_renderer.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>

namespace fs = std::filesystem;
using nlohmann::json;

namespace tp::stress {
namespace {

std::string verdict(const CaseResult& c) {
    return c.skipped ? "skipped" : c.pass ? "pass" : "FAIL";
}

json to_json(const CaseResult& c) {
    return {{"group", c.group},       {"case", c.name},        {"backend", c.backend},
            {"mode", c.mode},         {"nan", c.nan},          {"inf", c.inf},
            {"checked", c.checked},   {"verdict", verdict(c)}, {"expected", c.expected},
            {"measured", c.measured}, {"seconds", c.seconds}};
}

std::string escape(std::string s) {
    for (size_t i = 0; (i = s.find('|', i)) != std::string::npos; i += 2) s.replace(i, 1, "\\|");
    return s;
}

// stress.md: the run's facts, the verdict counts and a row per case and backend/mode.
std::string stress_report(const std::vector<CaseResult>& cases, const StressOptions& o,
                          const std::vector<std::string>& engines, double elapsed) {
    size_t pass = 0, fail = 0, skip = 0;
    uint64_t nan = 0, inf = 0;
    for (const CaseResult& c : cases) {
        (c.skipped ? skip : c.pass ? pass : fail)++;
        nan += c.nan;
        inf += c.inf;
    }
    std::string md = "# twinpath stress report\n\n";
    md +=
        fmt::format("Command: `{}`  \nEngines: {}  \nSizes: {}  \nElapsed: {:.1f} s\n\n", o.command,
                    fmt::join(engines, ", "), o.quick ? "CI (--quick)" : "large", elapsed);
    md += fmt::format("**{} passed, {} failed, {} skipped; NaN {}, Inf {} in all.** "
                      "Expected outcomes and their derivations: docs/stress.md.\n\n",
                      pass, fail, skip, nan, inf);
    md += "| group | case | backend/mode | NaN | Inf | checked | verdict | measured |\n";
    md += "|---|---|---|---:|---:|---:|---|---|\n";
    for (const CaseResult& c : cases)
        md +=
            fmt::format("| {} | {} | {}/{} | {} | {} | {} | {} | {} |\n", c.group, escape(c.name),
                        c.backend, c.mode, c.nan, c.inf, c.checked, verdict(c), escape(c.measured));
    return md;
}

} // namespace

int run_stress(const StressOptions& o) {
    const auto t0 = std::chrono::steady_clock::now();
    const Size s = o.quick ? small_size() : large_size();
    std::vector<CaseResult> cases;
    std::vector<std::string> engines;
    bool runtime_failure = false;
    auto add = [&](std::vector<CaseResult> v) {
        for (CaseResult& c : v) {
            fmt::print("stress: {}\n", describe(c));
            cases.push_back(std::move(c));
        }
    };
    auto skip = [&](const std::string& backend, const std::string& mode, const std::string& why) {
        CaseResult c;
        c.group = "all";
        c.name = "every render case";
        c.backend = backend;
        c.mode = mode;
        c.skipped = true;
        c.measured = why;
        add({c});
    };
    auto render_cases = [&](const Engine& e) {
        engines.push_back(e.backend + "/" + e.mode);
        add(scale_cases(e, s));
        add(position_cases(e, s));
        add(range_cases(e, s));
        add(dielectric_cases(e, s));
        add(degenerate_cases(e, s));
        add(light_cases(e, s));
        add(shading_normal_cases(e, s));
        add(accumulation_render_cases(e, s));
    };

    for (const std::string& b : o.backends) {
        if (b == "cpu") {
            add(film_accumulation_cases(s));
            add(brdf_cases_cpp(s));
            add(pbr_cases_cpp(s));
            add(watertight_cases_cpu(s, o.assets_dir));
            if (!o.self.empty())
                add({nan_vertex_case(o.self, (fs::path(o.out_dir) / "tmp").string())});
            render_cases(cpu_engine(o.threads));
            continue;
        }
        const std::optional<VkBackend> want =
            b.rfind("vulkan:", 0) == 0 ? parse_vk_backend(b.substr(7)) : std::nullopt;
        if (b != "vulkan" && !want) input_error("--backends: unknown backend '{}'", b);
        std::vector<VkBackend> backends;
        try {
            const std::vector<DeviceInfo> devices = list_vulkan_devices();
            const DeviceInfo& d = select_device(devices, o.device);
            // compute-wide (compute mode over the wide BVH) only when asked for by name.
            const std::vector<VkBackend> candidates =
                want ? std::vector<VkBackend>{*want}
                     : std::vector<VkBackend>{{VkMode::compute}, {VkMode::pipeline}};
            for (const VkBackend& v : candidates) {
                const std::string missing =
                    v.mode == VkMode::pipeline ? d.pipeline_missing : d.compute_missing;
                if (missing.empty())
                    backends.push_back(v);
                else
                    skip("vulkan", vk_backend_name(v), fmt::format("{} lacks {}", d.name, missing));
            }
        } catch (const RuntimeError& e) {
            skip("vulkan", want ? vk_backend_name(*want) : "any", e.what());
            continue;
        }
        for (const VkBackend& v : backends) {
            try {
                // Compute mode's ray queries cover both BVH layouts (watertight_cases_gpu).
                if (v.bvh == BvhLayout::binary) {
                    const VulkanContext ctx(o.device, v.mode);
                    if (v.mode == VkMode::compute) {
                        add(brdf_cases_glsl(ctx, s));
                        add(pbr_cases_glsl(ctx, s));
                        add(watertight_cases_gpu(ctx, s, o.assets_dir));
                    } else {
                        add(watertight_cases_pipeline(ctx, s, o.assets_dir));
                    }
                }
                render_cases(vulkan_engine(v, o.device));
            } catch (const RuntimeError& e) {
                runtime_failure = true;
                skip("vulkan", vk_backend_name(v), std::string("runtime failure: ") + e.what());
            }
        }
    }

    const double elapsed = seconds_since(t0);
    fs::create_directories(o.out_dir);
    json j;
    j["schema"] = "twinpath-stress/1";
    j["command"] = o.command;
    j["engines"] = engines;
    j["quick"] = o.quick;
    j["elapsed_s"] = elapsed;
    j["cases"] = json::array();
    bool all_pass = true;
    for (const CaseResult& c : cases) {
        j["cases"].push_back(to_json(c));
        all_pass = all_pass && (c.pass || c.skipped);
    }
    write_json((fs::path(o.out_dir) / "stress.json").string(), j);
    write_output_file((fs::path(o.out_dir) / "stress.md").string(),
                      stress_report(cases, o, engines, elapsed));
    fs::remove_all(fs::path(o.out_dir) / "tmp");
    fmt::print("stress: wrote {}/stress.md and stress.json ({} cases, {})\n", o.out_dir,
               cases.size(), all_pass ? "all passed" : "some FAILED");
    if (runtime_failure) return 3;
    return all_pass ? 0 : 1;
}

} // namespace tp::stress
