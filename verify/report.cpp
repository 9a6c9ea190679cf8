#include "verify/report.h"

#include "compare/report.h"
#include "compare/summary.h"
#include "image/exr_io.h"
#include "util/json_file.h"
#include "util/output_file.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>

namespace tp {
namespace {

using nlohmann::json;

// Single quotes where the shell would read a character otherwise.
std::string shell_word(const std::string& s) {
    const bool plain = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) ||
               std::string("-_./,=:+%@").find(c) != std::string::npos;
    });
    if (plain) return s;
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// A twinpath command line for commands.sh: its environment, the executable, the arguments.
std::string command(const std::vector<std::string>& environment,
                    const std::vector<std::string>& args) {
    std::string line;
    for (const std::string& e : environment) {
        const size_t eq = e.find('=');
        line += e.substr(0, eq + 1) + shell_word(e.substr(eq + 1)) + " ";
    }
    line += "\"$twinpath\"";
    for (const std::string& a : args) line += " " + shell_word(a);
    return line;
}

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

std::vector<std::string> render_args(const EngineRun& run, const std::vector<std::string>& out) {
    return concat(concat({"render"}, run.command), out);
}

std::string pair_dir(const VerifyResult& v, const PairVerdict& pv) {
    return engine_file_name(v.labels[pv.a]) + "_vs_" + engine_file_name(v.labels[pv.b]);
}

const char* limit_name(PlanLimit l) {
    switch (l) {
    case PlanLimit::Power:
        return "power";
    case PlanLimit::Budget:
        return "budget";
    case PlanLimit::Fixed:
        return "spp";
    case PlanLimit::NoNoise:
        return "no noise";
    }
    return "?";
}

json number_or_null(double x) {
    return std::isfinite(x) ? json(x) : json(nullptr);
}

json triage_json(const VerifyResult& v, const PairVerdict& pv) {
    const Triage& t = *pv.triage;
    json pixels = json::array();
    for (const PixelPaths& pp : t.paths) {
        json p = {{"x", pp.pixel.x},     {"y", pp.pixel.y},       {"z", pp.pixel.z},
                  {"why", pp.pixel.why}, {"samples", pp.samples}, {"diverged", pp.diff.diverged}};
        if (pp.diff.diverged)
            p.update({{"sample", pp.diff.sample},
                      {"vertex", pp.diff.vertex},
                      {"field", pp.diff.field},
                      {"value_a", pp.diff.value_a},
                      {"value_b", pp.diff.value_b},
                      {"why", pp.diff.why}});
        pixels.push_back(p);
    }
    json j = {{"geometry_identical", t.aov.identical()},
              {"aov", exact_verdict_line(t.aov)},
              {"log_seed", v.seeds.log},
              {"pixels", pixels},
              {"first_divergence", nullptr}};
    if (t.first) j["first_divergence"] = pixels[*t.first];
    return j;
}

void write_triage_files(const std::string& dir, const VerifyResult& v, const PairVerdict& pv,
                        std::vector<std::string>& script) {
    const Triage& t = *pv.triage;
    const std::string a = engine_file_name(v.labels[pv.a]), b = engine_file_name(v.labels[pv.b]);
    const std::string rel = pair_dir(v, pv) + "/";
    write_exr(dir + "/aov-" + a + ".exr", t.aov_a.image);
    write_exr(dir + "/aov-" + b + ".exr", t.aov_b.image);
    write_json(dir + "/aov.json", exact_json(t.aov));
    script.push_back(
        fmt::format("# Triage of {} against {}: the AOVs at the pixel centres, exactly "
                    "(exit 0: the same geometry)",
                    v.labels[pv.a], v.labels[pv.b]));
    for (const auto& [run, name] : {std::pair{&t.aov_a, a}, std::pair{&t.aov_b, b}})
        script.push_back(
            command(run->environment, render_args(*run, {"-o", rel + "aov-" + name + ".exr"})));
    script.push_back(command({}, {"compare", "--exact", rel + "aov-" + a + ".exr",
                                  rel + "aov-" + b + ".exr", "--json", rel + "aov.json"}));
    script.push_back("# The path logs of the pixels compare found most significant, with one seed "
                     "on both engines, and pathdiff (exit 1: diverging)");
    std::string tables;
    for (const PixelPaths& pp : t.paths) {
        const std::string stem = fmt::format("path-{}-{}", pp.pixel.x, pp.pixel.y);
        for (const auto& [run, name] : {std::pair{&pp.run_a, a}, std::pair{&pp.run_b, b}}) {
            write_output_file(dir + "/" + stem + "-" + name + ".json",
                              run->path_log.dump(1) + "\n");
            script.push_back(
                command(run->environment,
                        render_args(*run, {"-o", rel + stem + "-" + name + ".exr", "--debug-log",
                                           rel + stem + "-" + name + ".json"})));
        }
        script.push_back(command(
            {}, {"pathdiff", rel + stem + "-" + a + ".json", rel + stem + "-" + b + ".json"}));
        tables += fmt::format("$ twinpath pathdiff {0}-{1}.json {0}-{2}.json\n{3}\n", stem, a, b,
                              pp.diff.report);
    }
    write_output_file(dir + "/pathdiff.txt", tables);
}

} // namespace

std::string engine_file_name(const std::string& label) {
    std::string s = label;
    std::replace(s.begin(), s.end(), ' ', '-');
    return s;
}

void write_verify_report(const std::string& dir, const VerifyResult& v, const ReportContext& ctx) {
    std::filesystem::create_directories(dir);
    std::vector<std::string> script = {
        "#!/bin/sh",
        "# Every step of",
        "#   " + ctx.command_line,
        "# by hand (docs/debugging.md). Run it in this directory: each command rewrites its file",
        "# with the same pixels (a render's image depends only on its flags and seed).",
        "twinpath=${TWINPATH:-" + shell_word(ctx.twinpath) + "}",
        "",
        "# 1. Pilots, with seeds of their own: the noise and the cost of a sample on each engine",
    };
    json engines = json::array();
    for (size_t k = 0; k < v.labels.size(); ++k) {
        const std::string name = engine_file_name(v.labels[k]);
        write_exr(dir + "/pilot-" + name + ".exr", v.pilots[k].image);
        write_exr(dir + "/" + name + ".exr", v.images[k].image);
        if (!v.pilots[k].command.empty())
            script.push_back(command(v.pilots[k].environment,
                                     render_args(v.pilots[k], {"-o", "pilot-" + name + ".exr"})));
        engines.push_back({{"label", v.labels[k]},
                           {"device", v.images[k].device},
                           {"file", name + ".exr"},
                           {"pilot",
                            {{"spp", v.pilots[k].result.stats.spp},
                             {"seed", v.seeds.pilot[k]},
                             {"setup_s", v.pilots[k].setup_s},
                             {"sampling_s", v.pilots[k].sampling_s},
                             {"seconds_per_spp", v.costs[k].seconds_per_spp},
                             {"kept_spp", v.costs[k].kept_spp}}},
                           {"image",
                            {{"spp", v.images[k].result.stats.spp},
                             {"planned_spp", v.plan.spp[k]},
                             {"seed", v.seeds.image[k]},
                             {"setup_s", v.images[k].setup_s},
                             {"sampling_s", v.images[k].sampling_s}}}});
    }
    script.push_back("");
    script.push_back(
        "# 2. The images: independent seeds, the planned spp, rendered at once by verify");
    for (size_t k = 0; k < v.labels.size(); ++k)
        if (!v.images[k].command.empty())
            script.push_back(
                command(v.images[k].environment,
                        render_args(v.images[k], {"-o", engine_file_name(v.labels[k]) + ".exr"})));
    script.push_back("");
    script.push_back(fmt::format("# 3. compare at alpha {} / {} (exit 0: consistent, 1: different)",
                                 v.alpha, v.pairs.size()));
    json pairs = json::array();
    for (const PairVerdict& pv : v.verdicts) {
        const std::string pd = pair_dir(v, pv);
        const std::string full = dir + "/" + pd;
        std::filesystem::create_directories(full);
        write_report(full, pv.compare, v.rgb[pv.a], v.rgb[pv.b]);
        write_json(full + "/compare.json", compare_json(pv.compare, v.rgb[pv.a], v.rgb[pv.b]));
        script.push_back("mkdir -p " + shell_word(pd));
        script.push_back(command({}, {"compare", engine_file_name(v.labels[pv.a]) + ".exr",
                                      engine_file_name(v.labels[pv.b]) + ".exr", "--alpha",
                                      fmt::format("{}", pv.compare.alpha), "--report", pd, "--json",
                                      pd + "/compare.json"}));
        json pj = {{"a", v.labels[pv.a]},
                   {"b", v.labels[pv.b]},
                   {"verdict", pv.compare.different ? "different" : "consistent"},
                   {"p_value", pv.compare.p_value},
                   {"alpha", pv.compare.alpha},
                   {"line", compare_verdict_line(pv.compare)},
                   {"power_at_detect", pv.power},
                   {"detectable", number_or_null(pv.detectable)},
                   {"report", pd + "/index.html"},
                   {"triage", nullptr}};
        if (pv.triage) {
            script.push_back("");
            write_triage_files(full, v, pv, script);
            pj["triage"] = triage_json(v, pv);
        }
        pairs.push_back(pj);
    }
    std::string text;
    for (const std::string& l : script) text += l + "\n";
    write_output_file(dir + "/commands.sh", text);
    std::filesystem::permissions(dir + "/commands.sh", std::filesystem::perms::owner_exec,
                                 std::filesystem::perm_options::add);

    const Plan& p = v.plan;
    json plan = {{"detect", v.request.detect},
                 {"power", v.request.power},
                 {"alpha", v.alpha},
                 {"level", p.level},
                 {"limit", limit_name(p.limit)},
                 {"spp", p.spp},
                 {"predicted_wall_s", p.wall_s},
                 {"needed_wall_s", number_or_null(p.needed_wall_s)},
                 {"power_at_detect", p.power},
                 {"detectable", number_or_null(p.detectable)},
                 {"budget_s", v.request.budget_s ? json(*v.request.budget_s) : json(nullptr)}};
    const json j = {
        {"command", ctx.command_line},
        {"verdict", v.different() ? "different" : "consistent"},
        {"engines", engines},
        {"plan", plan},
        {"wall_s",
         {{"pilots", v.pilot_wall_s}, {"images", v.image_wall_s}, {"triage", v.triage_wall_s}}},
        {"pairs", pairs}};
    write_json(dir + "/verify.json", j);
}

} // namespace tp
