// Every bad-input path of `twinpath compare`: exit code 2 and a message that names the file
// (or the option) at fault; NaN/Inf values are counted in the message.
#include "image/exr_io.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <limits>

using namespace tp;
using namespace tp::test;

namespace {

// A 4x4 image: R, G, B = 0.5, and variance.R/G/B = 0.01 when `variance`.
ExrImage small_image(bool variance, int w = 4, int h = 4) {
    ExrImage img;
    img.width = w;
    img.height = h;
    for (const char* c : {"R", "G", "B"}) img.channels[c].assign(size_t(w * h), 0.5f);
    if (variance)
        for (const char* c : {"variance.R", "variance.G", "variance.B"})
            img.channels[c].assign(size_t(w * h), 0.01f);
    img.integers["twinpath:spp"] = 16;
    return img;
}

struct Fixture {
    std::string dir = temp_dir("compare-bad-input");
    std::string good = write("good.exr", small_image(true));

    std::string write(const std::string& name, const ExrImage& img) {
        const std::string path = dir + "/" + name;
        write_exr(path, img);
        return path;
    }
    ProcessResult compare(const std::string& args) {
        return run(shell_quote(twinpath_bin()) + " compare " + args);
    }
    // Exit 2, and the output contains every one of `expected`.
    void expect_bad(const std::string& args, std::initializer_list<std::string> expected) {
        const ProcessResult r = compare(args);
        INFO("twinpath compare " << args << "\n" << r.out);
        CHECK(r.exit_code == 2);
        for (const std::string& e : expected) CHECK(r.out.find(e) != std::string::npos);
    }
};

} // namespace

TEST_CASE("bad input: files that are missing, unreadable or of different sizes",
          "[compare][bad-input][cli]") {
    Fixture f;
    const std::string missing = f.dir + "/missing.exr";
    f.expect_bad(shell_quote(f.good) + " " + shell_quote(missing), {missing, "no such file"});
    const std::string text = f.dir + "/text.exr";
    std::ofstream(text) << "not an image";
    f.expect_bad(shell_quote(text) + " " + shell_quote(f.good), {text, "not a readable OpenEXR"});
    const std::string big = f.write("big.exr", small_image(true, 8, 4));
    f.expect_bad(shell_quote(f.good) + " " + shell_quote(big), {big, "8x4", f.good, "4x4"});
    // --exact checks sizes too.
    f.expect_bad("--exact " + shell_quote(f.good) + " " + shell_quote(big), {big, "8x4"});
}

TEST_CASE("bad input: missing colour channels, partial or absent variance",
          "[compare][bad-input][cli]") {
    Fixture f;
    ExrImage no_g = small_image(true);
    no_g.channels.erase("G");
    const std::string p_no_g = f.write("no_g.exr", no_g);
    f.expect_bad(shell_quote(p_no_g) + " " + shell_quote(f.good), {p_no_g, "no channel G"});

    ExrImage partial = small_image(true);
    partial.channels.erase("variance.B");
    const std::string p_partial = f.write("partial.exr", partial);
    f.expect_bad(shell_quote(f.good) + " " + shell_quote(p_partial),
                 {p_partial, "only some of variance"});

    const std::string a = f.write("a_novar.exr", small_image(false));
    const std::string b = f.write("b_novar.exr", small_image(false));
    f.expect_bad(shell_quote(a) + " " + shell_quote(b), {a, b, "variance"});

    ExrImage nothing_shared;
    nothing_shared.width = nothing_shared.height = 4;
    nothing_shared.channels["Z"].assign(16, 1.0f);
    const std::string z = f.write("z.exr", nothing_shared);
    f.expect_bad("--exact " + shell_quote(f.good) + " " + shell_quote(z),
                 {z, "no channel in common"});
}

TEST_CASE("bad input: NaN, Inf and negative variance are counted and named",
          "[compare][bad-input][cli]") {
    Fixture f;
    ExrImage nan = small_image(true);
    nan.channels["R"][5] = std::numeric_limits<float>::quiet_NaN();
    nan.channels["G"][5] = std::numeric_limits<float>::infinity();
    nan.channels["variance.B"][9] = std::numeric_limits<float>::quiet_NaN();
    const std::string p_nan = f.write("nan.exr", nan);
    // 3 values in 2 pixels; the first is pixel 5 = (1, 1) of a 4-wide image.
    f.expect_bad(shell_quote(f.good) + " " + shell_quote(p_nan),
                 {p_nan, "3 NaN/Inf values in 2 pixels", "R 1", "G 1", "variance.B 1", "(1, 1)"});

    ExrImage neg = small_image(true);
    neg.channels["variance.G"][2] = -0.5f;
    const std::string p_neg = f.write("neg.exr", neg);
    f.expect_bad(shell_quote(p_neg) + " " + shell_quote(f.good), {p_neg, "negative variance"});

    ExrImage zero_spp = small_image(true);
    zero_spp.integers["twinpath:spp"] = 0;
    const std::string p_zero = f.write("zero_spp.exr", zero_spp);
    f.expect_bad(shell_quote(f.good) + " " + shell_quote(p_zero), {p_zero, "twinpath:spp is 0"});

    // The JSON consumer is told why there is no result.
    const std::string json = f.dir + "/bad.json";
    f.compare(shell_quote(f.good) + " " + shell_quote(p_nan) + " --json " + shell_quote(json));
    const auto j = nlohmann::json::parse(std::ifstream(json));
    CHECK(j["verdict"] == "bad input");
    CHECK(j["error"].get<std::string>().find("3 NaN/Inf values") != std::string::npos);
}

TEST_CASE("bad usage: arguments and options", "[compare][bad-input][cli]") {
    Fixture f;
    const std::string g = shell_quote(f.good);
    f.expect_bad(g, {"two images", "got 1"});
    f.expect_bad(g + " " + g + " " + g, {"two images", "got 3"});
    f.expect_bad(g + " " + g + " --alpha 0", {"--alpha"});
    f.expect_bad(g + " " + g + " --alpha 1.5", {"--alpha"});
    f.expect_bad(g + " " + g + " --tolerance 0.1", {"--tolerance"}); // needs --exact
    f.expect_bad("--convergence " + g + " " + g, {"--reference"});
    f.expect_bad("--exact " + g, {"--exact compares two images", "got 1"});
    f.expect_bad("--convergence --reference " + g + " " + g, {"two or more spp", "got 1"});

    // --convergence: every image needs its spp, and two different spp are needed.
    ExrImage no_spp = small_image(true);
    no_spp.integers.clear();
    const std::string p_no_spp = f.write("no_spp.exr", no_spp);
    f.expect_bad("--convergence --reference " + g + " " + g + " " + shell_quote(p_no_spp),
                 {p_no_spp, "twinpath:spp"});
    f.expect_bad("--convergence --reference " + g + " " + g + " " + g,
                 {"two or more different spp"});
}
