// The Slurm farm (scripts/slurm/, docs/farm.md) on a one-node cluster started for the test
// (local_slurm.sh): a 4-task array renders a small scene, the dependent job merges, and the
// result equals one render of the same total spp; a re-submission after a lost part renders
// only that part. When the daemons cannot start here, the test says why on a line starting
// "twinpath-skip:", which CTest reports as a skip (tests/farm/CMakeLists.txt).
#include "split_check.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <thread>

namespace fs = std::filesystem;
using tp::test::run;
using tp::test::shell_quote;

namespace {

const std::string kRenderArgs = "--width 16 --height 16 --max-depth 4";

std::string farm_script(const std::string& name) {
    return tp::test::source_dir() + "/" + name;
}

// The cluster's daemons, stopped when the test ends however it ends.
struct LocalCluster {
    std::string dir;
    std::string conf;
    ~LocalCluster() {
        run(shell_quote(farm_script("tests/farm/local_slurm.sh")) + " stop " + shell_quote(dir));
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    tp::test::ProcessResult slurm(const std::string& command) const {
        return run("SLURM_CONF=" + shell_quote(conf) + " " + command);
    }
    // Waits until no job is queued or running; false after ten minutes, a guard against a hang
    // and not a measure: the array and its merge job take seconds on an idle machine, and a
    // loaded 2-core one may be many times slower (docs/testing.md).
    bool wait_idle() const {
        for (int i = 0; i < 3000; ++i) {
            const auto q = slurm("squeue -h -o %i");
            if (q.exit_code == 0 && q.out.find_first_not_of(" \n") == std::string::npos)
                return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
        }
        return false;
    }
};

} // namespace

TEST_CASE("a 4-task Slurm array and its merge job equal one render", "[farm][slurm]") {
    // munged checks that every directory above its socket is searchable by all: /tmp, not
    // the build tree.
    char cluster_dir[] = "/tmp/twinpath-slurm-XXXXXX";
    REQUIRE(mkdtemp(cluster_dir) != nullptr);
    LocalCluster cluster{cluster_dir, std::string(cluster_dir) + "/slurm.conf"};
    const auto start = run(shell_quote(farm_script("tests/farm/local_slurm.sh")) + " start " +
                           shell_quote(cluster.dir));
    if (start.exit_code == 77) {
        std::cout << start.out << std::flush; // the "twinpath-skip:" line and the logs
        WARN(start.out);
        return;
    }
    INFO(start.out);
    REQUIRE(start.exit_code == 0);

    const std::string work = tp::test::temp_dir("slurm"), out = work + "/render";
    const std::string submit = shell_quote(farm_script("scripts/slurm/submit.sh")) +
                               " --scene cornell --spp 8 --parts 4 --out " + shell_quote(out) +
                               " --twinpath " + shell_quote(tp::test::twinpath_bin()) + " -- " +
                               kRenderArgs;
    const auto first = cluster.slurm(submit);
    INFO(first.out);
    REQUIRE(first.exit_code == 0);
    CHECK_THAT(first.out, Catch::Contains("rendering parts 0,1,2,3 of 4"));
    REQUIRE(cluster.wait_idle());

    std::vector<std::string> parts;
    for (int i = 0; i < 4; ++i) parts.push_back(out + "/part_000" + std::to_string(i) + ".exr");
    for (const std::string& p : parts) REQUIRE(fs::exists(p));
    REQUIRE(fs::exists(out + "/merged.exr"));
    const std::string single = tp::test::render_part(out, "single.exr", "--spp 8 --film full");
    tp::test::check_merged_equals_single(out + "/merged.exr", parts, single);

    // A lost part: the re-submission renders it alone and merges again.
    fs::remove(parts[2]);
    fs::remove(out + "/merged.exr");
    const auto again = cluster.slurm(submit);
    INFO(again.out);
    REQUIRE(again.exit_code == 0);
    CHECK_THAT(again.out, Catch::Contains("rendering parts 2 of 4"));
    REQUIRE(cluster.wait_idle());
    REQUIRE(fs::exists(out + "/merged.exr"));
    tp::test::check_merged_equals_single(out + "/merged.exr", parts, single);
    fs::remove_all(work);
}
