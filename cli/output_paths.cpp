#include "output_paths.h"

#include "util/error.h"

#include <unistd.h>

#include <filesystem>

namespace tp {
namespace {

namespace fs = std::filesystem;

// An output file can be written when its directory exists and is writable and the path is not
// a directory or a read-only file: so a bad path fails at once (exit 2) and leaves no file
// behind, instead of failing after the work.
void check_output_path(const std::string& option, const std::string& path) {
    if (path.empty()) input_error("{}: the path is empty", option);
    const fs::path p(path);
    const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        input_error("{} {}: the directory {} does not exist", option, path, dir.string());
    if (fs::is_directory(p, ec)) input_error("{} {}: is a directory", option, path);
    if (access(dir.c_str(), W_OK) != 0)
        input_error("{} {}: the directory {} is not writable", option, path, dir.string());
    if (fs::exists(p, ec) && access(p.c_str(), W_OK) != 0)
        input_error("{} {}: the file is not writable", option, path);
}

// The file a path names: symbolic links and ".." resolved as far as the path exists.
fs::path identity(const std::string& path) {
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(fs::absolute(path), ec);
    return ec ? fs::absolute(path).lexically_normal() : p;
}

} // namespace

void check_output_paths(const std::vector<std::pair<std::string, std::string>>& outputs) {
    for (const auto& [option, path] : outputs) check_output_path(option, path);
    // A device (/dev/null) may take several outputs: none of them replaces it.
    const auto device = [](const std::string& path) {
        std::error_code ec;
        return fs::exists(path, ec) && !fs::is_regular_file(path, ec);
    };
    for (size_t i = 0; i < outputs.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (identity(outputs[i].second) == identity(outputs[j].second) &&
                !device(outputs[i].second))
                input_error("{} {} and {} {} name the same file", outputs[j].first,
                            outputs[j].second, outputs[i].first, outputs[i].second);
}

} // namespace tp
