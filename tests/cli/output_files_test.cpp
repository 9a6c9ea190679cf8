// The files a command writes (README, "Using it": every output is checked before any work): a
// device named as an output is written in place and stays a device; a write that fails says why
// (the system's reason), exits 3 and leaves no partial file or empty report directory; two outputs
// naming one file, an empty path and NaN option values are usage errors (exit 2).
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using tp::test::run;
using tp::test::shell_quote;

namespace {

std::string q(const fs::path& p) {
    return shell_quote(p.string());
}

// A character device node like /dev/null (1, 3) or /dev/full (1, 7), made in `dir` so that a
// regression replaces this node and not the system's. Needs root (CAP_MKNOD).
bool make_device(const fs::path& path, unsigned minor) {
    return ::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, minor)) == 0;
}

bool is_device(const fs::path& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

// A command run with file sizes limited to 0 bytes and SIGXFSZ ignored: every write to a
// regular file fails with EFBIG ("File too large"), as a full file system fails with ENOSPC;
// writes to devices are not limited.
std::string no_space(const std::string& command) {
    return "trap '' XFSZ; ulimit -f 0; " + command;
}

// A tiny render: the furnace scene, 8x8, one sample.
std::string render(const std::string& args) {
    return tp::test::twinpath("render furnace --spp 1 --width 8 --height 8 " + args);
}

} // namespace

TEST_CASE("outputs naming devices are written in place and the devices stay devices",
          "[cli][output]") {
    const fs::path dir = tp::test::temp_dir("output-device");
    const fs::path null = dir / "null", full = dir / "full";
    if (!make_device(null, 3) || !make_device(full, 7)) {
        WARN("cannot create device nodes here (not root?): the device cases did not run");
        return;
    }
    SECTION("every output of render into a null device: exit 0") {
        const auto r = run(render("-o " + q(null) + " --png " + q(null) + " --stats " + q(null)));
        INFO(r.out);
        CHECK(r.exit_code == 0);
        CHECK(is_device(null));
        CHECK_FALSE(fs::exists(dir / "null.partial"));
    }
    SECTION("-o, --png, --stats into a full device: exit 3 with the reason") {
        for (const std::string option : {"-o ", "--png ", "--stats "}) {
            const std::string other = option == "-o " ? "" : "-o " + q(null) + " ";
            const auto r = run(render(other + option + q(full)));
            INFO(option << "\n" << r.out);
            CHECK(r.exit_code == 3);
            CHECK(r.out.find("No space left on device") != std::string::npos);
            CHECK(is_device(full));
            CHECK_FALSE(fs::exists(dir / "full.partial"));
        }
    }
    SECTION("compare --json into a null device") {
        const fs::path a = dir / "a.exr";
        REQUIRE(run(render("-o " + q(a))).exit_code == 0);
        const auto r =
            run(tp::test::twinpath("compare " + q(a) + " " + q(a) + " --json " + q(null)));
        INFO(r.out);
        CHECK(r.exit_code == 0);
        CHECK(is_device(null));
    }
    fs::remove_all(dir);
}

TEST_CASE("a write that fails exits 3 with the reason and leaves no partial file",
          "[cli][output]") {
    const fs::path dir = tp::test::temp_dir("output-full");
    const fs::path exr = dir / "out.exr", json = dir / "out.json";
    // Before: --stats and --debug-log left a 0-byte file (the stream's state was checked before
    // it was flushed), --stats exited 0, --debug-log gave no reason.
    const struct {
        const char* name;
        std::string args;
        fs::path file;
    } cases[] = {
        {"-o", "-o " + q(exr), exr},
        {"--png", "-o /dev/null --png " + q(dir / "out.png"), dir / "out.png"},
        {"--stats", "-o /dev/null --stats " + q(json), json},
        {"--debug-log", "-o /dev/null --debug-pixel 1,1 --debug-log " + q(json), json},
    };
    for (const auto& c : cases) {
        const auto r = run(no_space(render(c.args)));
        INFO(c.name << "\n" << r.out);
        CHECK(r.exit_code == 3);
        CHECK(r.out.find("cannot write " + c.file.string() + ": File too large") !=
              std::string::npos);
        CHECK_FALSE(fs::exists(c.file));
        CHECK_FALSE(fs::exists(c.file.string() + ".partial"));
    }
    SECTION("compare --report leaves no directory") {
        REQUIRE(run(render("-o " + q(exr))).exit_code == 0);
        const fs::path report = dir / "report";
        const auto r = run(no_space(
            tp::test::twinpath("compare " + q(exr) + " " + q(exr) + " --report " + q(report))));
        INFO(r.out);
        CHECK(r.exit_code == 3);
        CHECK(r.out.find("File too large") != std::string::npos);
        CHECK_FALSE(fs::exists(report));
    }
    fs::remove_all(dir);
}

TEST_CASE("two outputs naming one file and empty output paths are usage errors", "[cli][output]") {
    const fs::path dir = tp::test::temp_dir("output-names");
    const fs::path exr = dir / "same.exr";
    // Before: exit 0, and same.exr held the PNG.
    const struct {
        const char* name;
        std::string args, expected;
    } cases[] = {
        {"-o and --png", "-o " + q(exr) + " --png " + q(exr), "name the same file"},
        {"-o and --stats through another spelling",
         "-o " + q(exr) + " --stats " + q(dir / "." / "same.exr"), "name the same file"},
        {"--stats and --debug-log",
         "-o " + q(exr) + " --stats " + q(dir / "s.json") + " --debug-pixel 1,1 --debug-log " +
             q(dir / "s.json"),
         "name the same file"},
        {"-o ''", "-o ''", "-o: the path is empty"},
        {"--png ''", "-o " + q(exr) + " --png ''", "--png: the path is empty"},
    };
    for (const auto& c : cases) {
        const auto r = run(render(c.args));
        INFO(c.name << "\n" << r.out);
        CHECK(r.exit_code == 2);
        CHECK(r.out.find(c.expected) != std::string::npos);
        CHECK_FALSE(fs::exists(exr));
    }
    const auto r = run(tp::test::twinpath("compare a.exr b.exr --json ''"));
    INFO(r.out);
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("--json: the path is empty") != std::string::npos);
    fs::remove_all(dir);
}

// /proc's directory passes every permission check for root, but its file system creates no
// files: the check creates the output's PATH.partial once, so this is a usage error before the
// render (exit 2), not a failed write after it (exit 3).
TEST_CASE("an output in a directory that takes no new files is a usage error before any work",
          "[cli][output]") {
    const auto r = run(render("-o /proc/twinpath-test.exr"));
    INFO(r.out);
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("cannot create a file in /proc") != std::string::npos);
    CHECK(r.out.find("twinpath: rendering") == std::string::npos);
}

TEST_CASE("NaN option values are usage errors", "[cli][output]") {
    const fs::path dir = tp::test::temp_dir("option-nan");
    const fs::path a = dir / "a.exr";
    REQUIRE(run(render("-o " + q(a))).exit_code == 0);
    // Before: --time-limit nan rendered (exit 0), and compare answered "different" (exit 1).
    const struct {
        const char* name;
        std::string command, option;
    } cases[] = {
        {"render --time-limit nan", render("-o " + q(dir / "b.exr") + " --time-limit nan"),
         "--time-limit"},
        {"compare --floor nan", tp::test::twinpath("compare " + q(a) + " " + q(a) + " --floor nan"),
         "--floor"},
        {"compare --exact --tolerance nan",
         tp::test::twinpath("compare " + q(a) + " " + q(a) + " --exact --tolerance nan"),
         "--tolerance"},
        {"pathdiff --geometry-tolerance nan",
         tp::test::twinpath("pathdiff a.json b.json --geometry-tolerance nan"),
         "--geometry-tolerance"},
    };
    for (const auto& c : cases) {
        const auto r = run(c.command);
        INFO(c.name << "\n" << r.out);
        CHECK(r.exit_code == 2);
        CHECK(r.out.find(c.option) != std::string::npos);
    }
    CHECK_FALSE(fs::exists(dir / "b.exr"));
    fs::remove_all(dir);
}
