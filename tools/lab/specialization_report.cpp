#include "tools/lab/specialization_report.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>

using nlohmann::json;

namespace tp::lab {
namespace {

// The register count of a variant's path loop: the first statistic named like "Register Count"
// (NVIDIA), "... registers ..." or "VGPRs" (AMD) of the executable of the compute or
// ray-generation stage, which holds the path loop; null when the driver reports none.
json register_count(const json& pipeline) {
    if (!pipeline.is_object()) return nullptr;
    for (const json& e : pipeline.value("executables", json::array())) {
        const json stages = e.value("stages", json::array());
        if (std::find(stages.begin(), stages.end(), "compute") == stages.end() &&
            std::find(stages.begin(), stages.end(), "raygen") == stages.end())
            continue;
        for (const json& st : e.value("statistics", json::array())) {
            std::string name = st.value("name", "");
            std::transform(name.begin(), name.end(), name.begin(),
                           [](unsigned char c) { return char(std::tolower(c)); });
            if ((name.find("register") != std::string::npos || name == "vgprs") &&
                st.value("value", json()).is_number())
                return st["value"];
        }
    }
    return nullptr;
}

} // namespace

std::string specialization_section(const json& r) {
    // A register column when the driver reported register counts (--pipeline-stats).
    bool registers = false;
    for (const json& sc : r["scenes"])
        for (const json& row : sc.value("specialization", json::array()))
            registers = registers ||
                        register_count(row["specialized"].value("pipeline", json())).is_number();
    std::string md = fmt::format(
        "### Specialization\n\nTime per spp of the path loop with every feature compiled in "
        "(`--features all`) over the loop specialized to the scene's features; > 1 means the "
        "specialized loop is faster. GPU time where the device measures it, else wall time; "
        "best of {} alternating rounds of {} spp each, same seed.{}\n\n"
        "| scene | backend/mode | features | all, ms/spp | specialized, ms/spp | ratio |{}\n"
        "|---|---|---|---:|---:|---:|{}\n",
        r["settings"].value("spec_rounds", 0), r["settings"].value("spec_spp", 0),
        registers ? " Registers: the driver's register count of the path loop's stage (compute "
                    "or ray generation), all features → specialized (`--pipeline-stats`)."
                  : "",
        registers ? " registers |" : "", registers ? "---:|" : "");
    const auto count = [](const json& v) { return v.is_number() ? v.dump() : std::string("-"); };
    const auto ms = [](const json& v) {
        return v.is_number() ? fmt::format("{:.3g}", v.get<double>() * 1e3) : std::string("-");
    };
    for (const json& sc : r["scenes"]) {
        if (!sc.contains("specialization")) continue;
        for (const json& row : sc["specialization"]) {
            std::string features;
            for (const json& f : row["features"])
                features += (features.empty() ? "" : ", ") + f.get<std::string>();
            const bool gpu = row["ratio_gpu"].is_number();
            const char* key = gpu ? "gpu_per_spp_s" : "wall_per_spp_s";
            md += fmt::format("| {} | {}/{} | {} | {} | {} | {:.3f}{} |",
                              sc["name"].get<std::string>(), row["backend"].get<std::string>(),
                              row["mode"].get<std::string>(), features.empty() ? "none" : features,
                              ms(row["all"][key]), ms(row["specialized"][key]),
                              row["ratio"].get<double>(), gpu ? " (GPU)" : "");
            if (registers)
                md += fmt::format(
                    " {} → {} |", count(register_count(row["all"].value("pipeline", json()))),
                    count(register_count(row["specialized"].value("pipeline", json()))));
            md += "\n";
        }
    }
    return md + "\n";
}

} // namespace tp::lab
