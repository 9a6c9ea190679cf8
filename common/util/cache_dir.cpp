#include "util/cache_dir.h"

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace tp {
namespace {

// The variable's value; "" when it is unset or empty.
std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

} // namespace

std::string cache_dir() {
    if (const std::string dir = env("TWINPATH_CACHE"); !dir.empty()) return dir;
    if (const std::string xdg = env("XDG_CACHE_HOME"); !xdg.empty())
        return (fs::path(xdg) / "twinpath").string();
    if (const std::string home = env("HOME"); !home.empty())
        return (fs::path(home) / ".cache" / "twinpath").string();
    return "";
}

} // namespace tp
