#include "tools/lab/result_fields.h"

using nlohmann::json;

namespace tp::lab {

double secondary_rays(const json& rays) {
    return rays["extension"].get<double>() + rays["shadow"].get<double>();
}

bool has_section(const json& result, const char* name) {
    for (const json& s : result["sections"])
        if (s == name) return true;
    return false;
}

std::string run_label(const json& run) {
    const std::string label =
        run["backend"].get<std::string>() + "/" + run["mode"].get<std::string>();
    const std::string sampler = run.value("sampler", "random");
    return sampler == "random" ? label : label + " " + sampler;
}

} // namespace tp::lab
