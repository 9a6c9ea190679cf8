// --report DIR: the page loads in headless Chromium (Debian's chromium package) and every
// image in it decodes; the numbers on the page are the ones in --json.
#include "renders.h"

#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>

using namespace tp;
using namespace tp::test;

namespace {

// The DOM after the load event (--dump-dom), from a fresh profile each time. `timeout 120` is a
// guard against a hung browser, not a measure: the page loads in seconds even on a loaded
// 2-core machine.
std::string dump_dom(const std::string& html) {
    const std::string profile = temp_dir("chromium-profile");
    const ProcessResult r = run(fmt::format(
        "timeout 120 {} --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
        "--disable-background-networking --disable-component-update --disable-sync "
        "--user-data-dir={} --dump-dom {} 2>/dev/null",
        shell_quote(TWINPATH_TEST_CHROMIUM), shell_quote(profile), shell_quote("file://" + html)));
    return r.out;
}

size_t count(const std::string& s, const std::string& what) {
    size_t n = 0;
    for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
    return n;
}

void require_chromium() {
    if (std::string(TWINPATH_TEST_CHROMIUM).empty() ||
        !std::filesystem::exists(TWINPATH_TEST_CHROMIUM))
        FAIL("chromium not found at configure time (Debian package `chromium`)");
}

// `twinpath compare dir/a.exr dir/b.exr --report dir/report --json dir/r.json`.
ProcessResult compare_with_report(const std::string& dir) {
    return run(fmt::format("{} compare {} {} --report {} --json {}", shell_quote(twinpath_bin()),
                           shell_quote(dir + "/a.exr"), shell_quote(dir + "/b.exr"),
                           shell_quote(dir + "/report"), shell_quote(dir + "/r.json")));
}

} // namespace

TEST_CASE("report: every image loads in headless Chromium and the page carries the verdict",
          "[compare][report][cli]") {
    require_chromium();
    const std::string dir = temp_dir("report");
    RenderSpec a;
    a.width = a.height = 32;
    a.seed = 1;
    RenderSpec b = a;
    b.seed = 2;
    b.max_depth = 1; // a biased B: the page must say "different"
    render_cpu_file(a, dir + "/a.exr");
    render_cpu_file(b, dir + "/b.exr");
    const ProcessResult r = compare_with_report(dir);
    INFO(r.out);
    REQUIRE(r.exit_code == 1);
    const std::string page = dir + "/report/index.html";
    for (const char* png : {"a.png", "b.png", "difference.png", "z.png", "tiles.png"})
        CHECK(std::filesystem::file_size(dir + "/report/" + png) > 0);

    const std::string dom = dump_dom(page);
    INFO(dom.substr(0, 2000));
    CHECK(dom.find("data-images-loaded=\"5/5\"") != std::string::npos);
    CHECK(count(dom, "data-loaded=\"yes\"") == 5);
    CHECK(dom.find("twinpath compare: different") != std::string::npos);
    // The global p-value shown is the one in the JSON (same formatting, 3 significant digits).
    const auto j = nlohmann::json::parse(std::ifstream(dir + "/r.json"));
    CHECK(dom.find(fmt::format("p = {:.3g}", j["p_value"].get<double>())) != std::string::npos);

    // The check itself can fail: a missing image is reported as not loaded.
    std::filesystem::remove(dir + "/report/z.png");
    const std::string broken = dump_dom(page);
    CHECK(broken.find("data-images-loaded=\"4/5\"") != std::string::npos);
    CHECK(count(broken, "data-loaded=\"no\"") == 1);
}

TEST_CASE("report at unequal spp shows the pixels whose variance was borrowed",
          "[compare][report][cli][unequal-spp]") {
    require_chromium();
    const std::string dir = temp_dir("report-unequal");
    RenderSpec a;
    a.scene = "cornell_spheres";
    a.width = a.height = 32;
    a.seed = 3;
    RenderSpec b = a;
    b.spp = 128;
    b.seed = 4;
    render_cpu_file(a, dir + "/a.exr");
    render_cpu_file(b, dir + "/b.exr");
    const ProcessResult r = compare_with_report(dir);
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("A:B spp ratio 1:8, variance borrowed in"));
    const auto j = nlohmann::json::parse(std::ifstream(dir + "/r.json"));
    CHECK(j["variance"]["borrower"] == "a");
    CHECK(j["variance"]["spp_ratio"] == 8.0);
    const size_t borrowed = j["variance"]["pixel_channels_borrowed"];
    CHECK(borrowed > 0);
    CHECK(borrowed < 3u * 32u * 32u); // A's own variance is the larger one somewhere

    const std::string dom = dump_dom(dir + "/report/index.html");
    INFO(dom.substr(0, 2000));
    CHECK(dom.find("data-images-loaded=\"6/6\"") != std::string::npos);
    CHECK(dom.find(fmt::format("{} of {} pixel-channels", borrowed, 3 * 32 * 32)) !=
          std::string::npos);
}
