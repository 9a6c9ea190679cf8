#include "tools/lab/report_files.h"

#include "bench/result_json.h"
#include "tools/lab/result_fields.h"
#include "tools/lab/sizes_report.h"
#include "tools/lab/svg_plot.h"
#include "util/output_file.h"

#include <fmt/format.h>

#include <filesystem>

namespace fs = std::filesystem;
using nlohmann::json;
using tp::bench::ImageSize;
using tp::bench::mrays_per_s;
using tp::bench::parse_image_sizes;

namespace tp::lab {
namespace {

// One CSV field: numbers as they are, null empty, strings quoted when they need it (RFC 4180).
std::string field(const json& v) {
    if (v.is_null()) return "";
    if (v.is_number_float()) return fmt::format("{:.6g}", v.get<double>());
    if (v.is_number()) return v.dump();
    const std::string s = v.is_string() ? v.get<std::string>() : v.dump();
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string row(std::initializer_list<json> fields) {
    std::string line;
    for (const json& f : fields) line += (line.empty() ? "" : ",") + field(f);
    return line + "\n";
}

std::string ladder_csv(const json& result) {
    std::string csv =
        "scene,backend,mode,sampler,device,spp,wall_s,gpu_s,relmse,relmse_excess,mape,"
        "efficiency,camera_rays,extension_rays,shadow_rays,camera_mrays_s,"
        "extension_mrays_s,shadow_mrays_s,mrays_s\n";
    for (const json& sc : result["scenes"])
        for (const json& run : sc.value("ladder", json::array()))
            for (const json& p : run["points"]) {
                const double t = p["wall_s"];
                csv +=
                    row({sc["name"], run["backend"], run["mode"], run.value("sampler", "random"),
                         run["device"], p["spp"], t, p["gpu_s"], p["relmse"], p["relmse_excess"],
                         p["mape"], p["efficiency"], p["rays"]["camera"], p["rays"]["extension"],
                         p["rays"]["shadow"], mrays_per_s(p["rays"], "camera", t),
                         mrays_per_s(p["rays"], "extension", t),
                         mrays_per_s(p["rays"], "shadow", t), mrays_per_s(p["rays"], nullptr, t)});
            }
    return csv;
}

std::string table_csv(const json& result) {
    std::string csv = "scene,backend,mode,device,accel_bytes,sweep,depth,spp,wall_s,gpu_s,"
                      "camera_rays,extension_rays,shadow_rays,mrays_s,secondary_rays_per_sample\n";
    for (const json& sc : result["scenes"])
        for (const json& run : sc.value("table", json::array()))
            for (const char* sweep : {"depth_rows", "spp_rows"})
                for (const json& r : run[sweep]) {
                    const double t = r["wall_s"], samples = r["samples"];
                    const double secondary = secondary_rays(r["rays"]);
                    csv += row(
                        {sc["name"], run["backend"], run["mode"], run["device"], run["accel_bytes"],
                         sweep == std::string("depth_rows") ? "depth" : "spp", r["depth"], r["spp"],
                         t, r["gpu_s"], r["rays"]["camera"], r["rays"]["extension"],
                         r["rays"]["shadow"], mrays_per_s(r["rays"], nullptr, t),
                         samples > 0 ? json(secondary / samples) : json(nullptr)});
                }
    return csv;
}

std::string peer_csv(const json& result) {
    std::string csv = "scene,width,height,spp,max_depth,threads,ours_time_per_spp_s,"
                      "ours_mrays_s,peer_time_per_spp_s,peer_mrays_s_inferred,speedup\n";
    for (const json& sc : result["scenes"]) {
        if (!sc.contains("peer")) continue;
        const json& peer = sc["peer"];
        for (const json& r : peer["rows"])
            csv +=
                row({sc["name"], sc["width"], sc["height"], peer["spp"], sc["max_depth"],
                     r["threads"], r["ours"]["time_per_spp_s"], r["ours"]["mrays_per_s"],
                     r["peer"]["time_per_spp_s"], r["peer"]["mrays_per_s_inferred"], r["speedup"]});
    }
    return csv;
}

std::string sizes_csv(const json& result) {
    std::string csv = "scene,backend,mode,device,timer,width,height,pixels,spp,wall_s,gpu_s,"
                      "camera_rays,extension_rays,shadow_rays,mrays_s,ratio_to_base,base\n";
    std::vector<std::string> words;
    for (const json& w : result["settings"]["sizes"]["list"]) words.push_back(w);
    const ImageSize base = ratio_base(parse_image_sizes(words));
    for (const json& sc : result["scenes"])
        for (const json& run : sc.value("sizes", json::array())) {
            const std::vector<json> ratios = rate_ratios(run, base);
            for (size_t i = 0; i < run["points"].size(); ++i) {
                const json& p = run["points"][i];
                csv += row({sc["name"], run["backend"], run["mode"], run["device"], run["timer"],
                            p["width"], p["height"], p["pixels"], p["spp"], p["wall_s"], p["gpu_s"],
                            p["rays"]["camera"], p["rays"]["extension"], p["rays"]["shadow"],
                            p["mrays_s"], ratios[i], base.name()});
            }
        }
    return csv;
}

} // namespace

void write_csv_files(const json& result, const std::string& dir) {
    if (has_section(result, "ladder"))
        write_output_file((fs::path(dir) / "ladder.csv").string(), ladder_csv(result));
    if (has_section(result, "table"))
        write_output_file((fs::path(dir) / "table.csv").string(), table_csv(result));
    if (has_section(result, "peer"))
        write_output_file((fs::path(dir) / "peer.csv").string(), peer_csv(result));
    if (has_section(result, "sizes"))
        write_output_file((fs::path(dir) / "sizes.csv").string(), sizes_csv(result));
}

void write_plots(json& result, const std::string& dir) {
    for (json& sc : result["scenes"]) {
        if (sc.contains("sizes") && !sc["sizes"].empty()) {
            const std::string rel = "plots/sizes/" + sc["name"].get<std::string>() + ".svg";
            fs::create_directories(fs::path(dir) / "plots" / "sizes");
            write_output_file((fs::path(dir) / rel).string(), svg_line_plot(sizes_plot(sc)));
            sc["sizes_plot"] = rel;
        }
        if (!sc.contains("ladder") || sc["ladder"].empty()) continue;
        LinePlot plot;
        plot.title = fmt::format("{}: relMSE against time ({}x{})", sc["name"].get<std::string>(),
                                 sc["width"].get<int>(), sc["height"].get<int>());
        plot.x_label = "wall time [s]";
        plot.y_label = "relMSE (excess over reference noise)";
        plot.guides = {1e-2, 1e-3};
        for (const json& run : sc["ladder"]) {
            PlotSeries s;
            s.label = run_label(run);
            for (const json& p : run["points"])
                s.points.emplace_back(p["wall_s"].get<double>(), p["relmse_excess"].get<double>());
            plot.series.push_back(s);
        }
        const std::string rel = "plots/" + sc["name"].get<std::string>() + ".svg";
        fs::create_directories(fs::path(dir) / "plots");
        write_output_file((fs::path(dir) / rel).string(), svg_line_plot(plot));
        sc["plot"] = rel;
    }
}

} // namespace tp::lab
