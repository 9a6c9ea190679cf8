#include "tools/lab/render_result.h"

#include "tools/lab/markdown.h"
#include "tools/lab/report_files.h"
#include "util/error.h"
#include "util/output_file.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using nlohmann::json;

namespace tp::lab {
namespace {

json read_result(const std::string& path) {
    std::ifstream in(path);
    if (!in) input_error("{}: cannot open file", path);
    json r;
    try {
        r = json::parse(in);
    } catch (const json::exception& e) {
        input_error("{}: not a JSON file: {}", path, e.what());
    }
    if (r.value("schema", "") != "twinpath-bench/1")
        input_error("{}: not a twinpath bench result (schema twinpath-bench/1)", path);
    return r;
}

// The plots, CSV files and bench.md into `dir`, and the section merged into `markdown` when one
// is given. The plots' paths go into `r` (write_plots) for the markdown's links.
void write_derived_files(json& r, const std::string& dir, const std::string& markdown) {
    write_plots(r, dir);
    write_csv_files(r, dir);
    write_output_file((fs::path(dir) / "bench.md").string(), markdown_section(r, "."));
    if (markdown.empty()) return;
    const fs::path md_dir = fs::absolute(markdown).parent_path();
    const std::string section = r["section"].get<std::string>();
    merge_markdown_section(
        markdown, section,
        markdown_section(r, fs::relative(fs::absolute(dir), md_dir).generic_string()));
    fmt::print("lab: section '{}' of {}\n", section, markdown);
}

} // namespace

void render_result(const std::string& path, const std::string& markdown) {
    json r = read_result(path);
    const std::string dir = fs::absolute(path).parent_path().string();
    try {
        write_derived_files(r, dir, markdown);
    } catch (const json::exception& e) {
        input_error("{}: a field of the bench result is missing or malformed: {}", path, e.what());
    }
    fmt::print("lab: wrote bench.md, CSV and plots beside {}\n", path);
}

} // namespace tp::lab
