// SIGINT and SIGTERM during a render (issue 23, item 5; README, "Interrupting a render"): the
// first signal ends the render after the pass in flight and writes what was accumulated, a valid
// image whose twinpath:spp says how many samples it holds, then exits 130 or 143; a second
// signal exits at once and leaves no partial file. Before, the first signal killed the process
// and nothing was written.
#include "image/exr_io.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

// twinpath with `args`, its output into `log`; returns the process id.
pid_t spawn(const std::vector<std::string>& args, const fs::path& log) {
    const pid_t pid = fork();
    if (pid == 0) {
        const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(fd, STDOUT_FILENO);
        dup2(fd, STDERR_FILENO);
        std::vector<char*> argv;
        const std::string bin = tp::test::twinpath_bin();
        argv.push_back(const_cast<char*>(bin.c_str()));
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(bin.c_str(), argv.data());
        _exit(127);
    }
    return pid;
}

// CPU seconds the process has used (utime + stime of /proc/PID/stat), -1 once it is gone.
double cpu_seconds(pid_t pid) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t close = text.rfind(')');
    if (close == std::string::npos) return -1.0;
    std::istringstream fields(text.substr(close + 2));
    std::string f;
    double utime = 0, stime = 0;
    for (int i = 3; i <= 15 && fields >> f; ++i) {
        if (i == 14) utime = std::stod(f);
        if (i == 15) stime = std::stod(f);
    }
    return (utime + stime) / double(sysconf(_SC_CLK_TCK));
}

// Waits until the process has rendered for `seconds` of CPU time (loading the scene takes a few
// milliseconds of it). False when it ended or 60 s passed first.
bool rendering_for(pid_t pid, double seconds) {
    const auto t0 = Clock::now();
    while (Clock::now() - t0 < std::chrono::seconds(60)) {
        int status = 0;
        if (waitpid(pid, &status, WNOHANG) != 0) return false;
        if (cpu_seconds(pid) >= seconds) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
}

// The exit code, or -1 when it was killed by a signal or took longer than 60 s (then killed).
int exit_code(pid_t pid) {
    const auto t0 = Clock::now();
    int status = 0;
    while (waitpid(pid, &status, WNOHANG) == 0) {
        if (Clock::now() - t0 > std::chrono::seconds(60)) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            return -1;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The render of every case: the Cornell box at 16 x 16 (a CPU pass is 1024 spp, under a
// second), far more samples than the test waits for.
std::vector<std::string> render_args(const std::vector<std::string>& backend, const fs::path& out,
                                     const std::string& spp) {
    std::vector<std::string> a = {
        "render", "cornell", "--width", "16", "--height",   "16",      "--seed",
        "7",      "--spp",   spp,       "-o", out.string(), "--stats", (out.string() + ".json")};
    a.insert(a.end(), backend.begin(), backend.end());
    return a;
}

// One signal: the image holds n whole passes, and it is the image that --spp n renders (same
// seed): the counter-based random numbers make those the same samples. Channel values agree to
// `tol` relative (the film sums per pass in double on the CPU; the GPU sums its batches in
// float, so a different batch plan rounds differently).
void check_first_signal(const std::vector<std::string>& backend, int sig, double tol) {
    const fs::path dir = tp::test::temp_dir("interrupt");
    const fs::path out = dir / "a.exr", log = dir / "a.log";
    const pid_t pid = spawn(render_args(backend, out, "1000000"), log);
    REQUIRE(rendering_for(pid, 1.0));
    kill(pid, sig);
    const int code = exit_code(pid);
    INFO(read_text(log));
    REQUIRE(code == 128 + sig);
    CHECK(read_text(log).find("interrupted") != std::string::npos);
    CHECK_FALSE(fs::exists(out.string() + ".partial"));
    const tp::ExrImage a = tp::read_exr(out.string());
    const int64_t n = a.integers.at("twinpath:spp");
    CHECK(n >= 1);
    CHECK(n < 1000000);
    CHECK(tp::test::read_json(out.string() + ".json")["spp"] == n);

    const fs::path ref = dir / "b.exr";
    const auto r = tp::test::run(tp::test::twinpath(
        "render cornell --width 16 --height 16 --seed 7 --spp " + std::to_string(n) + " -o " +
        tp::test::shell_quote(ref.string()) + " " + [&] {
            std::string s;
            for (const std::string& b : backend) s += b + " ";
            return s;
        }()));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const tp::ExrImage b = tp::read_exr(ref.string());
    double worst = 0.0;
    for (const char* c : {"R", "G", "B", "variance.R", "variance.G", "variance.B"})
        for (size_t i = 0; i < a.channel(c).size(); ++i) {
            const double x = a.channel(c)[i], y = b.channel(c)[i];
            worst = std::max(worst, std::abs(x - y) / std::max({std::abs(x), std::abs(y), 1e-30}));
        }
    CHECK(worst <= tol);
    fs::remove_all(dir);
}

// Two signals: exit at once with 128 + the second's number, nothing written. The second is sent
// once the first has been handled (its note is in the log): sent together, the two may reach
// two threads at once and either be the first. The image is 2048 x 2048, so that a pass (one
// sample per pixel, several seconds) cannot end between the two.
void check_second_signal(const std::vector<std::string>& backend) {
    const fs::path dir = tp::test::temp_dir("interrupt-twice");
    const fs::path out = dir / "a.exr", log = dir / "a.log";
    std::vector<std::string> args = render_args(backend, out, "1000000");
    for (size_t i = 0; i + 1 < args.size(); ++i)
        if (args[i] == "--width" || args[i] == "--height") args[i + 1] = "2048";
    const pid_t pid = spawn(args, log);
    REQUIRE(rendering_for(pid, 0.5));
    kill(pid, SIGINT);
    const auto sent = Clock::now();
    while (read_text(log).find("finishing the pass") == std::string::npos &&
           Clock::now() - sent < std::chrono::seconds(10))
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    kill(pid, SIGTERM);
    const auto t0 = Clock::now();
    const int code = exit_code(pid);
    INFO(read_text(log));
    CHECK(code == 128 + SIGTERM);
    // "At once": far below the pass the first signal would have waited for.
    CHECK(Clock::now() - t0 < std::chrono::milliseconds(500));
    CHECK_FALSE(fs::exists(out));
    CHECK_FALSE(fs::exists(out.string() + ".partial"));
    fs::remove_all(dir);
}

} // namespace

TEST_CASE("SIGINT during a CPU render writes the samples accumulated and exits 130",
          "[cli][interrupt]") {
    check_first_signal({"--backend", "cpu"}, SIGINT, 1e-6);
}

TEST_CASE("SIGTERM during a CPU render writes the samples accumulated and exits 143",
          "[cli][interrupt]") {
    check_first_signal({"--backend", "cpu"}, SIGTERM, 1e-6);
}

TEST_CASE("a second signal ends a CPU render at once", "[cli][interrupt]") {
    check_second_signal({"--backend", "cpu"});
}

TEST_CASE("SIGINT during a Vulkan compute render writes the samples accumulated and exits 130",
          "[cli][interrupt][gpu]") {
    check_first_signal({"--backend", "vulkan", "--vk-mode", "compute"}, SIGINT, 1e-4);
}
