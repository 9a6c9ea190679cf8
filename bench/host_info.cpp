#include "bench/host_info.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

namespace tp::bench {
namespace {

// Quotes an argument for a POSIX shell when it holds anything beyond a safe set.
std::string shell_word(const std::string& s) {
    const bool safe =
        !s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyz"
                                          "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_-+=.,/:@%") == std::string::npos;
    if (safe) return s;
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

} // namespace

std::string command_line() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    const std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string out;
    size_t start = 0;
    for (size_t i = 0; i < raw.size(); ++i) {
        if (raw[i] != '\0') continue;
        std::string arg = raw.substr(start, i - start);
        if (start == 0) arg = std::filesystem::path(arg).filename().string();
        out += (out.empty() ? "" : " ") + shell_word(arg);
        start = i + 1;
    }
    return out;
}

std::array<double, 3> load_average() {
    std::array<double, 3> l{-1, -1, -1};
    std::ifstream in("/proc/loadavg");
    in >> l[0] >> l[1] >> l[2];
    return l;
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            const size_t colon = line.find(':');
            if (colon != std::string::npos && colon + 2 <= line.size())
                return line.substr(colon + 2);
        }
    return "unknown CPU";
}

unsigned cpu_cores() {
    return std::max(1u, std::thread::hardware_concurrency());
}

std::string utc_timestamp() {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm utc{};
    gmtime_r(&now, &utc);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return buf;
}

} // namespace tp::bench
