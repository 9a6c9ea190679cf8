#include "tools/lab/markdown.h"

#include "bench/result_json.h"
#include "tools/lab/efficiency_report.h"
#include "tools/lab/frame_loop_report.h"
#include "tools/lab/result_fields.h"
#include "tools/lab/sizes_report.h"
#include "tools/lab/specialization_report.h"
#include "util/output_file.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using nlohmann::json;
using tp::bench::mrays_per_s;

namespace tp::lab {
namespace {

constexpr const char* kDash = "–";

// Three significant digits, or a dash for null.
std::string g3(const json& v) {
    return v.is_number() ? fmt::format("{:.3g}", v.get<double>()) : kDash;
}

std::string g3(double v) {
    return fmt::format("{:.3g}", v);
}

// Seconds as milliseconds, three significant digits, or a dash for null.
std::string ms(const json& seconds) {
    return seconds.is_number() ? g3(1e3 * seconds.get<double>()) : kDash;
}

std::string lights_text(const json& l) {
    return fmt::format("{} point, {} directional, {} emissive triangles, environment {}",
                       l["point"].get<int>(), l["directional"].get<int>(),
                       l["emissive_triangles"].get<int>(), l["environment"].get<std::string>());
}

std::string facts(const json& r) {
    const json& h = r["host"];
    const json& s = r["settings"];
    std::string devices;
    for (const json& b : r["backends"])
        devices += fmt::format("{}`{}`: {}", devices.empty() ? "" : "; ", run_label(b),
                               b["device"].get<std::string>());
    const auto load = [](const json& l) {
        return fmt::format("{:.2f} / {:.2f} / {:.2f}", l[0].get<double>(), l[1].get<double>(),
                           l[2].get<double>());
    };
    std::string md = "| | |\n|---|---|\n";
    md += fmt::format("| command | `{}` |\n", r["command"].get<std::string>());
    md += fmt::format("| devices | {} |\n", devices.empty() ? kDash : devices);
    md += fmt::format("| host | {}, {} logical cores |\n", h["cpu"].get<std::string>(),
                      h["cores"].get<int>());
    md += fmt::format("| load average (1/5/15 min) | {} before, {} after: other processes "
                      "may have shared the machine |\n",
                      load(h["load_average_start"]), load(h["load_average_end"]));
    md += fmt::format("| when | {} ({:.0f} s), twinpath {} |\n", r["started"].get<std::string>(),
                      r["elapsed_s"].get<double>(), r["renderer_version"].get<std::string>());
    md += fmt::format("| image | {}×{} |\n\n", s["width"].get<int>(), s["height"].get<int>());
    return md;
}

std::string ladder_section(const json& r, const std::string& base) {
    const json& s = r["settings"];
    std::string md = fmt::format(
        "### Error against time\n\n"
        "One render per backend/mode with snapshots at 1, 2, 4, … {} spp (seed {}), each against "
        "a CPU reference of {} spp (seed independent of the measured renders). relMSE is the "
        "excess over the reference's own noise (`compare --convergence`), ε = 1/(relMSE · t) the "
        "thesis's efficiency (§2.6); times to reach relMSE 10⁻² and 10⁻³ are read off the "
        "log-log fit of relMSE against time and given only when the ladder got there. The "
        "full ladders are in `ladder.csv`.\n\n",
        s["max_spp"].get<int>(), s["seed"].get<int>(), s["ref_spp"].get<int>());
    for (const json& sc : r["scenes"]) {
        if (!sc.contains("ladder")) continue;
        const json& ref = sc["reference"];
        md += fmt::format("**{}**: {} triangles ({} unique); {}; max depth {}; reference {} spp "
                          "({}, {:.3g} s on the CPU)",
                          sc["name"].get<std::string>(), sc["triangles"].get<uint64_t>(),
                          sc["unique_triangles"].get<uint64_t>(), lights_text(sc["lights"]),
                          sc["max_depth"].get<int>(), ref["spp"].get<int>(),
                          ref["cached"].get<bool>() ? "cached" : "rendered now",
                          ref["render_s"].get<double>());
        if (sc.contains("plot"))
            md += fmt::format("; [plot]({})",
                              (fs::path(base) / sc["plot"].get<std::string>()).generic_string());
        md += "\n\n| backend/mode | spp | time [s] | GPU [s] | relMSE | MAPE | ε | ε / ε(cpu) | "
              "Mrays/s camera / extension / shadow | t to 10⁻² [s] | t to 10⁻³ [s] |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|\n";
        double cpu_eff = 0;
        for (const json& run : sc["ladder"])
            if (run["backend"] == "cpu" && run.value("sampler", "random") == "random" &&
                run["points"].back()["efficiency"].is_number())
                cpu_eff = run["points"].back()["efficiency"];
        for (const json& run : sc["ladder"]) {
            const json& p = run["points"].back();
            const double t = p["wall_s"];
            const auto rate = [&](const char* k) { return g3(mrays_per_s(p["rays"], k, t)); };
            const json& to = run["time_to_relmse"];
            md +=
                fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} / {} / {} | {} | {} |\n",
                            run_label(run), p["spp"].get<int>(), g3(t), g3(p["gpu_s"]),
                            g3(p["relmse_excess"]), g3(p["mape"]), g3(p["efficiency"]),
                            cpu_eff > 0 && p["efficiency"].is_number()
                                ? g3(p["efficiency"].get<double>() / cpu_eff)
                                : kDash,
                            rate("camera"), rate("extension"), rate("shadow"),
                            to["1e-2"].is_null() ? "not reached" : g3(to["1e-2"]),
                            to["1e-3"].is_null() ? "not reached" : g3(to["1e-3"]));
        }
        md += "\n";
    }
    return md;
}

// One block of Table 5.3: rows are the sweep values, a column triple per scene.
std::string sweep_block(const json& r, const std::string& backend, const char* rows,
                        const char* key, const char* key_name) {
    std::string head = fmt::format("| {} |", key_name), rule = "|---|";
    std::vector<const json*> runs;
    for (const json& sc : r["scenes"]) {
        if (!sc.contains("table")) continue;
        for (const json& run : sc["table"]) // a reference into r: runs keeps pointers
            if (run_label(run) == backend) {
                const std::string n = sc["name"];
                head += fmt::format(" {0} T [s] | {0} Mrays/s | {0} sec. rays/sample |", n);
                rule += "---|---|---|";
                runs.push_back(&run);
            }
    }
    std::string md = head + "\n" + rule + "\n";
    const size_t n_rows = runs.empty() ? 0 : (*runs[0])[rows].size();
    for (size_t i = 0; i < n_rows; ++i) {
        md += fmt::format("| {} |", (*runs[0])[rows][i][key].get<int>());
        for (const json* run : runs) {
            const json& x = (*run)[rows][i];
            const double t = x["wall_s"], samples = x["samples"];
            md += fmt::format(" {} | {} | {} |", g3(t), g3(mrays_per_s(x["rays"], nullptr, t)),
                              samples > 0 ? g3(secondary_rays(x["rays"]) / samples) : kDash);
        }
        md += "\n";
    }
    return md + "\n";
}

std::string table_section(const json& r) {
    const json& ts = r["settings"]["table"];
    std::string md = fmt::format(
        "### Rays per second over depth and samples (thesis Table 5.3)\n\n"
        "Russian roulette off (every path that stays in the scene reaches depth D). T is the "
        "render time without setup; Mrays/s counts camera, extension and shadow rays; secondary "
        "rays per sample are extension + shadow rays per pixel sample. The spp rows are "
        "snapshots of one render. Numbers in `table.csv`.\n\n");
    // Scene facts, and the acceleration-structure memory per backend.
    std::vector<std::string> backends;
    std::string head = "| |", rule = "|---|", tri = "| triangles |", uniq = "| unique triangles |",
                lights = "| lights |";
    for (const json& sc : r["scenes"]) {
        if (!sc.contains("table")) continue;
        head += fmt::format(" {} |", sc["name"].get<std::string>());
        rule += "---|";
        tri += fmt::format(" {} |", sc["triangles"].get<uint64_t>());
        uniq += fmt::format(" {} |", sc["unique_triangles"].get<uint64_t>());
        lights += fmt::format(" {} |", lights_text(sc["lights"]));
        for (const json& run : sc["table"])
            if (std::find(backends.begin(), backends.end(), run_label(run)) == backends.end())
                backends.push_back(run_label(run));
    }
    md += head + "\n" + rule + "\n" + tri + "\n" + uniq + "\n" + lights + "\n";
    for (const std::string& b : backends) {
        std::string mem = fmt::format("| {} BVH/AS memory [KB] |", b);
        for (const json& sc : r["scenes"]) {
            if (!sc.contains("table")) continue;
            std::string cell = kDash;
            for (const json& run : sc["table"])
                if (run_label(run) == b) {
                    cell = g3(run["accel_bytes"].get<double>() / 1024.0);
                    for (const auto& [k, v] : run["extra"].items())
                        if (k.size() > 6 && k.compare(k.size() - 6, 6, "_bytes") == 0)
                            cell += fmt::format(" ({} {:.3g})", k.substr(0, k.size() - 6),
                                                std::stod(v.get<std::string>()) / 1024.0);
                }
            mem += " " + cell + " |";
        }
        md += mem + "\n";
    }
    md += "\n";
    for (const std::string& b : backends) {
        md += fmt::format("#### {}: depth D at S = {} spp\n\n", b, ts["fixed_spp"].get<int>());
        md += sweep_block(r, b, "depth_rows", "depth", "D");
        md += fmt::format("#### {}: samples S at D = {}\n\n", b, ts["fixed_depth"].get<int>());
        md += sweep_block(r, b, "spp_rows", "spp", "S");
    }
    return md;
}

std::string peer_section(const json& r) {
    std::string md =
        "### Against Embree's path tracer tutorial (same run)\n\n"
        "Same scene (exported to OBJ; lights given on the tutorial's command line), camera, "
        "image, spp and path length; Russian roulette off in twinpath. Time per spp = (time at "
        "N spp − time at 1 spp) / (N − 1), best of 2, for both programs. The tutorial's rays "
        "are counted in one more, untimed, pair of runs (its two trace calls wrapped by "
        "`twinpath_ray_counter.so` through LD_PRELOAD; \"inferred\" where the module was "
        "missing: twinpath's rays per spp over the tutorial's time per spp). Speed-up = "
        "tutorial time / twinpath time, rays/s ratio = twinpath rays/s / tutorial rays/s "
        "(> 1: twinpath is faster). Absolute times on a shared CPU are indicative; the ratios "
        "are the result.\n\n"
        "| scene | image | spp | D | threads | twinpath [ms/spp] | twinpath rays/spp | "
        "twinpath Mrays/s | tutorial [ms/spp] | tutorial rays/spp | tutorial Mrays/s | speed-up "
        "| rays/s ratio |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    std::string scaling = "| scene | twinpath | tutorial |\n|---|---|---|\n", notes;
    for (const json& sc : r["scenes"]) {
        if (!sc.contains("peer")) continue;
        const json& p = sc["peer"];
        const json& rows = p["rows"];
        for (const json& row : rows) {
            const json& ours = row["ours"];
            const json& peer = row["peer"];
            const bool counted = peer.contains("mrays_per_s") && peer["mrays_per_s"].is_number();
            md += fmt::format(
                "| {} | {}×{} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                sc["name"].get<std::string>(), sc["width"].get<int>(), sc["height"].get<int>(),
                p["spp"].get<int>(), sc["max_depth"].get<int>(), row["threads"].get<int>(),
                ms(ours["time_per_spp_s"]), g3(ours["rays_per_spp"]), g3(ours["mrays_per_s"]),
                peer["exit_code"] == 0
                    ? ms(peer["time_per_spp_s"])
                    : fmt::format("failed (exit {})", peer["exit_code"].get<int>()),
                counted ? g3(peer["rays_per_spp"]) : std::string(kDash),
                counted ? g3(peer["mrays_per_s"])
                        : g3(peer["mrays_per_s_inferred"]) + " (inferred)",
                g3(row["speedup"]), g3(row.value("rays_per_s_ratio", json(nullptr))));
        }
        if (rows.size() >= 2) {
            const json &a = rows[0], &b = rows[rows.size() - 1];
            const auto ratio = [&](const char* who) {
                const json &ta = a[who]["time_per_spp_s"], &tb = b[who]["time_per_spp_s"];
                return ta.is_number() && tb.is_number() ? g3(ta.get<double>() / tb.get<double>())
                                                        : std::string(kDash);
            };
            scaling += fmt::format("| {} | {} | {} |\n", sc["name"].get<std::string>(),
                                   ratio("ours"), ratio("peer"));
        }
        for (const json& c : sc.value("peer_variant", json::array()))
            notes += fmt::format("- {}: {}\n", sc["name"].get<std::string>(), c.get<std::string>());
    }
    const json& th = r["settings"]["peer"]["threads"];
    if (th.size() >= 2)
        md += fmt::format("\nSpeed-up from {} to {} threads (time per spp at {} / at {}):\n\n{}",
                          th[0].get<int>(), th[th.size() - 1].get<int>(), th[0].get<int>(),
                          th[th.size() - 1].get<int>(), scaling);
    if (!notes.empty()) md += "\nScene changes for the comparison (both renderers):\n\n" + notes;
    return md + "\n";
}

} // namespace

std::string markdown_section(const json& r, const std::string& base) {
    std::string md = fmt::format("## {}\n\n", r["title"].get<std::string>());
    md += facts(r);
    if (has_section(r, "ladder")) md += ladder_section(r, base);
    if (has_section(r, "table")) md += table_section(r);
    if (has_section(r, "peer")) md += peer_section(r) + efficiency_markdown(r);
    if (has_section(r, "specialization")) md += specialization_section(r);
    if (has_section(r, "sizes")) md += sizes_section(r, base);
    if (has_section(r, "frame_loop")) md += frame_loop_section(r);
    if (!r["skipped"].empty()) {
        md += "Skipped:\n\n";
        for (const json& s : r["skipped"])
            md += fmt::format("- {}: {}\n", s["what"].get<std::string>(),
                              s["reason"].get<std::string>());
        md += "\n";
    }
    return md;
}

void merge_markdown_section(const std::string& path, const std::string& id,
                            const std::string& text) {
    std::string doc;
    if (fs::exists(path)) {
        std::ifstream in(path);
        std::stringstream ss;
        ss << in.rdbuf();
        doc = ss.str();
    } else {
        doc = "# Benchmarks\n\nGenerated by `twinpath bench` (see the sections' commands).\n\n";
    }
    const std::string begin = fmt::format("<!-- twinpath-bench:begin {} -->\n", id);
    const std::string end = fmt::format("<!-- twinpath-bench:end {} -->\n", id);
    const std::string block = begin + text + end;
    const size_t b = doc.find(begin), e = doc.find(end);
    if (b != std::string::npos && e != std::string::npos && e > b)
        doc.replace(b, e + end.size() - b, block);
    else
        doc += (doc.size() >= 2 && doc.compare(doc.size() - 2, 2, "\n\n") == 0 ? ""
                : doc.empty() || doc.back() == '\n'                            ? "\n"
                                                                               : "\n\n") +
               block;
    write_output_file(path, doc);
}

} // namespace tp::lab
