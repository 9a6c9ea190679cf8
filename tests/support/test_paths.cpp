#include "support/test_paths.h"

#include <array>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace tp::test {

std::string twinpath_bin() {
    return TWINPATH_TEST_BIN;
}
std::string lab_bin() {
    return TWINPATH_TEST_LAB_BIN;
}
std::string scenes_dir() {
    return TWINPATH_TEST_SCENES;
}
std::string assets_dir() {
    return TWINPATH_TEST_ASSETS;
}
std::string source_dir() {
    return TWINPATH_TEST_SOURCE;
}
std::string glslang_validator() {
    return TWINPATH_TEST_GLSLANG;
}

std::string temp_dir(const std::string& tag) {
    static std::atomic<int> counter{0};
    const auto dir =
        std::filesystem::temp_directory_path() /
        ("twinpath-test-" + tag + "-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

ProcessResult run(const std::string& command) {
    ProcessResult r;
    FILE* p = popen((command + " 2>&1").c_str(), "r");
    if (!p) throw std::runtime_error("popen failed: " + command);
    std::array<char, 4096> buf;
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
    const int status = pclose(p);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

std::string twinpath(const std::string& args) {
    return shell_quote(twinpath_bin()) + " " + args;
}

std::string twinpath_lab(const std::string& args) {
    return shell_quote(lab_bin()) + " " + args;
}

nlohmann::json read_json(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    return nlohmann::json::parse(in);
}

} // namespace tp::test
