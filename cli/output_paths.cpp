#include "output_paths.h"

#include "util/error.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

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
    // A regular file is written as PATH.partial and renamed (util/output_file.h): create that
    // file once now, so that a directory whose permission bits allow writing but whose file
    // system refuses new files (/proc, /sys, a read-only mount, root's exemption from the bits)
    // fails before the work too.
    if (fs::exists(p, ec) && !fs::is_regular_file(p, ec)) return; // a device: written in place
    const std::string partial = path + ".partial";
    const bool existed = fs::exists(partial, ec);
    const int fd = open(partial.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
        input_error("{} {}: cannot create a file in {}: {}", option, path, dir.string(),
                    std::strerror(errno));
    close(fd);
    if (!existed) unlink(partial.c_str());
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
