// SIGINT and SIGTERM during a render (README, "Interrupting a render"): the
// first signal ends the render after the pass in flight and writes what was accumulated, a valid
// image whose twinpath:spp says how many samples it holds, then exits 130 or 143; a second
// signal exits at once and leaves no partial file; a signal before the first pass exits at once.
// Every signal is sent after an event the program reports (its "rendering" line, its note, its
// handlers installed), never after a guessed time: start-up alone (the dynamic loader, before
// main) takes a sizeable and load-dependent share of a second of CPU time, so a process that has
// used some CPU time need not have got anywhere (docs/testing.md).
#include "image/exr_io.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
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

// How long a wait below gives up: a guard against a hang, never a measure. Every wait here ends
// on an event (a line in the log, a handler installed, an exit) that comes within seconds even
// on a loaded 2-core machine; the guard only keeps a broken build from hanging the suite.
constexpr auto kHangGuard = std::chrono::seconds(120);

// twinpath with `args`, its output into `log`; returns the process id.
pid_t spawn(const std::vector<std::string>& args, const fs::path& log) {
    const pid_t pid = fork();
    // A failed fork returns -1, and kill(-1, ...) would signal every process this user may.
    REQUIRE(pid >= 0);
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

// A spawned twinpath, killed and reaped when the test leaves early (a failed REQUIRE).
struct Child {
    pid_t pid;
    ~Child() {
        int status = 0;
        if (waitpid(pid, &status, WNOHANG) == 0) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
        }
    }
};

std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Whether the process has ended, without reaping it (exit_code reads its status later).
bool ended(pid_t pid) {
    siginfo_t info{};
    return waitid(P_PID, pid, &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid;
}

// Waits until `log` holds `text`. False when the process ended without it or the guard ran out.
bool log_says(pid_t pid, const fs::path& log, const std::string& text) {
    const auto t0 = Clock::now();
    while (Clock::now() - t0 < kHangGuard) {
        const bool gone = ended(pid); // before the read: a line written just before the end counts
        if (read_text(log).find(text) != std::string::npos) return true;
        if (gone) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
}

// Waits until twinpath (not the forked copy of this test, whose Catch2 handlers are caught
// signals too) catches SIGINT and SIGTERM: /proc/PID/exe is the binary, and SigCgt in
// /proc/PID/status has both bits. False when it ended or the guard ran out.
bool handlers_installed(pid_t pid) {
    const std::string proc = "/proc/" + std::to_string(pid);
    const uint64_t wanted = (uint64_t(1) << (SIGINT - 1)) | (uint64_t(1) << (SIGTERM - 1));
    const auto t0 = Clock::now();
    while (Clock::now() - t0 < kHangGuard) {
        std::error_code ec;
        if (fs::read_symlink(proc + "/exe", ec) == fs::path(tp::test::twinpath_bin())) {
            std::istringstream status(read_text(proc + "/status"));
            for (std::string line; std::getline(status, line);)
                if (line.rfind("SigCgt:", 0) == 0 &&
                    (std::stoull(line.substr(7), nullptr, 16) & wanted) == wanted)
                    return true;
        }
        if (ended(pid)) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
}

// The exit code, or -1 when it was killed by a signal or outlived the guard (then killed).
int exit_code(pid_t pid) {
    const auto t0 = Clock::now();
    int status = 0;
    while (waitpid(pid, &status, WNOHANG) == 0) {
        if (Clock::now() - t0 > kHangGuard) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            return -1;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The line twinpath writes when the first pass begins (cli/cmd_render.cpp): from then on a first
// signal saves the passes done. The tests signal after it, never after a guessed delay.
const std::string kRendering = "twinpath: rendering ";
const std::string kFinishing = "interrupted: finishing the pass in flight";

// `twinpath render SCENE` with `extra`, writing `out` and its statistics.
std::vector<std::string> render_args(const std::string& scene, const fs::path& out,
                                     const std::vector<std::string>& extra) {
    std::vector<std::string> a = {"render", scene,        "--seed",  "7",
                                  "-o",     out.string(), "--stats", (out.string() + ".json")};
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
}

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// The Cornell box at 16 x 16: a CPU pass is 1024 spp (under a second), far fewer samples than
// the render asks for.
const std::vector<std::string> kSmallCornell = {"--width", "16", "--height", "16"};

// One signal: the image holds n whole passes, and it is the image that --spp n renders (same
// seed): the counter-based random numbers make those the same samples. Channel values agree to
// `tol` relative (the film sums per pass in double on the CPU; the GPU sums its batches in
// float, so a different batch plan rounds differently).
void check_first_signal(const std::vector<std::string>& backend, int sig, double tol) {
    const fs::path dir = tp::test::temp_dir("interrupt");
    const fs::path out = dir / "a.exr", log = dir / "a.log";
    const Child child{spawn(
        render_args("cornell", out, concat(concat(kSmallCornell, {"--spp", "1000000"}), backend)),
        log)};
    REQUIRE(log_says(child.pid, log, kRendering));
    kill(child.pid, sig);
    const int code = exit_code(child.pid);
    const std::string text = read_text(log);
    INFO(text);
    REQUIRE(code == 128 + sig);
    // The handler's note comes before everything the stop leads to, the last line included.
    const size_t note = text.find(kFinishing), wrote = text.find("interrupted: wrote the");
    CHECK(note != std::string::npos);
    CHECK(wrote != std::string::npos);
    CHECK(note < wrote);
    CHECK_FALSE(fs::exists(out.string() + ".partial"));
    const tp::ExrImage a = tp::read_exr(out.string());
    const int64_t n = a.integers.at("twinpath:spp");
    CHECK(n >= 1);
    CHECK(n < 1000000);
    CHECK(tp::test::read_json(out.string() + ".json")["spp"] == n);

    const fs::path ref = dir / "b.exr";
    std::string command = "render cornell --width 16 --height 16 --seed 7 --spp " +
                          std::to_string(n) + " -o " + tp::test::shell_quote(ref.string());
    for (const std::string& b : backend) command += " " + b;
    const auto r = tp::test::run(tp::test::twinpath(command));
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
// two threads at once and either be the first. The pass in flight cannot end between the two on
// any machine: in the furnace (a closed sphere) with roulette off until depth 100000, every path
// makes 100000 bounces, and a 64 x 64 pass of 256 spp is some 10^11 rays, hours of work. So the
// exit code 143 (the first signal's path would exit 130 after writing) and the missing image
// show that the second signal did not wait for the pass; no clock is needed for "at once".
void check_second_signal(const std::vector<std::string>& backend) {
    const fs::path dir = tp::test::temp_dir("interrupt-twice");
    const fs::path out = dir / "a.exr", log = dir / "a.log";
    const Child child{spawn(
        render_args("furnace", out,
                    concat({"--spp", "1000000", "--min-depth", "100000", "--max-depth", "100000"},
                           backend)),
        log)};
    REQUIRE(log_says(child.pid, log, kRendering));
    kill(child.pid, SIGINT);
    REQUIRE(log_says(child.pid, log, kFinishing));
    kill(child.pid, SIGTERM);
    const int code = exit_code(child.pid);
    INFO(read_text(log));
    CHECK(code == 128 + SIGTERM);
    CHECK_FALSE(fs::exists(out));
    CHECK_FALSE(fs::exists(out.string() + ".partial"));
    CHECK_FALSE(fs::exists(out.string() + ".json"));
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

// Before the first pass there is nothing to save: a signal exits at once with its code and a
// note, and writes nothing. The scene is a FIFO that no one writes, so twinpath stays in its
// loader (before any pass) for as long as the test likes; the handlers must be installed by
// then, before the scene is read, or the signal's default action would end the process without
// a word or an exit code.
TEST_CASE("a signal before the first pass exits at once and writes nothing", "[cli][interrupt]") {
    const fs::path dir = tp::test::temp_dir("interrupt-early");
    const fs::path scene = dir / "scene.json", out = dir / "a.exr", log = dir / "a.log";
    REQUIRE(mkfifo(scene.c_str(), 0600) == 0);
    const Child child{spawn(render_args(scene.string(), out, {"--spp", "4"}), log)};
    REQUIRE(handlers_installed(child.pid));
    kill(child.pid, SIGTERM);
    const int code = exit_code(child.pid);
    const std::string text = read_text(log);
    INFO(text);
    CHECK(code == 128 + SIGTERM);
    CHECK(text.find("interrupted before rendering began: nothing to save") != std::string::npos);
    CHECK(text.find(kRendering) == std::string::npos);
    CHECK_FALSE(fs::exists(out));
    CHECK_FALSE(fs::exists(out.string() + ".json"));
    fs::remove_all(dir);
}

TEST_CASE("SIGINT during a Vulkan compute render writes the samples accumulated and exits 130",
          "[cli][interrupt][gpu]") {
    check_first_signal({"--backend", "vulkan", "--vk-mode", "compute"}, SIGINT, 1e-4);
}
