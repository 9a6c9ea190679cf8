// `twinpath-lab peer` at a tiny size through the real command line (docs/bench.md, "Peer
// comparisons"): next to Embree's path tracer tutorial and Blender's Cycles where they are
// installed, and the "peer absent" reports where not, into a bench result that `twinpath-lab
// markdown` renders; bad peer options exit 2. Never a timing: only that times are there.
#include "compare/rgb_image.h"
#include "file_readers.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;
using tp::test::read_csv;
using tp::test::read_file;
using tp::test::read_json;
using tp::test::run;
using tp::test::shell_quote;

namespace {

const std::string kPeerBinary = "/usr/bin/pathtracer"; // Embree's tutorial (embree-tools)

// `twinpath-lab peer` with the CI smoke size (--quick: 24x24, cornell, reference 32 spp, the
// tutorial at 1 and 2 spp, 0.2 s of sampling per renderer) and the given arguments, then
// `twinpath-lab markdown` on its result.
tp::test::ProcessResult peer(const std::string& args, const std::string& out,
                             const std::string& cache) {
    const auto p = run(tp::test::twinpath_lab("peer --quick " + args + " --out " +
                                              shell_quote(out) + " --cache " + shell_quote(cache)));
    if (p.exit_code != 0) return p;
    const auto m = run(tp::test::twinpath_lab("markdown " + shell_quote(out + "/bench.json")));
    INFO(m.out);
    REQUIRE(m.exit_code == 0);
    return p;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// The skipped entry whose `what` contains `what`, or null.
json skipped_entry(const json& result, const std::string& what) {
    for (const json& s : result["skipped"])
        if (contains(s["what"].get<std::string>(), what)) return s;
    return nullptr;
}

void check_peer_files(const std::string& out, const json& r, const tp::test::ProcessResult& p) {
    const std::string md = read_file(out + "/bench.md");
    CHECK(contains(md, "### Against Embree's path tracer tutorial"));
    const tp::test::Csv csv = read_csv(out + "/peer.csv");
    for (const char* column :
         {"scene", "threads", "ours_time_per_spp_s", "peer_time_per_spp_s", "speedup"})
        CHECK(std::count(csv.header.begin(), csv.header.end(), column) == 1);
    if (fs::exists(kPeerBinary)) {
        REQUIRE(r["scenes"][0].contains("peer"));
        const json& rows = r["scenes"][0]["peer"]["rows"];
        REQUIRE(rows.size() == 2); // threads 1 and 2
        for (const json& row : rows) {
            CHECK(row["peer"]["exit_code"] == 0);
            CHECK(row["ours"]["t_1spp_s"].is_number()); // measured, whatever its value
            CHECK(row["ours"]["t_nspp_s"].is_number());
        }
        CHECK(csv.rows.size() == 2);
        CHECK(fs::exists(r["scenes"][0]["peer"]["obj"].get<std::string>()));
        // The tutorial's counted rays (peer_ray_counter.c): each sample of each pixel starts
        // with one camera ray (rtcIntersect1), and a path of at most D scattering events under
        // the peer variant's single light traces at most D + 1 extension and D + 1 shadow rays.
        const json& sc = r["scenes"][0];
        const double pixels = sc["width"].get<double>() * sc["height"].get<double>();
        const double depth = sc["max_depth"].get<double>();
        const json& counted = rows[0]["peer"]["rays_per_spp"];
        REQUIRE(counted.is_number());
        CHECK(counted.get<double>() >= pixels);
        CHECK(counted.get<double>() <= 2.0 * (depth + 1.0) * pixels);
    } else {
        WARN("no " << kPeerBinary << ": checking the 'peer absent' report instead");
        CHECK(csv.rows.empty());
        CHECK(contains(p.out, "is not at " + kPeerBinary));
        CHECK(!skipped_entry(r, "peer").is_null());
    }
}

const std::string kBlender = "/usr/bin/blender"; // Cycles' host (Debian package blender)

// Mean of channel c over the left or right half of an image.
double half_mean(const tp::RgbImage& img, int c, bool right) {
    double sum = 0;
    const int x0 = right ? img.width / 2 : 0, x1 = right ? img.width : img.width / 2;
    for (int y = 0; y < img.height; ++y)
        for (int x = x0; x < x1; ++x) sum += img.mean[c][size_t(y) * img.width + x];
    return sum / (double(img.height) * (x1 - x0));
}

void check_efficiency(const std::string& out, const json& r) {
    const json& e = r["scenes"][0]["efficiency"];
    CHECK(
        contains(read_file(out + "/bench.md"), "### Time to error against a production renderer"));
    size_t ours = 0, peers = 0;
    for (const json& row : e["rows"]) {
        INFO(row.dump());
        CHECK(row["exit_code"] == 0);
        CHECK(row["spp"].get<int>() >= 2);
        CHECK(row["relmse"].is_number()); // measured, whatever its value
        ++(row.value("peer", false) ? peers : ours);
    }
    CHECK(ours == 2); // threads 1 and 2, the random sampler
    if (!fs::exists(kBlender)) {
        WARN("no " << kBlender << ": checking the 'peer absent' report instead");
        CHECK(peers == 0);
        CHECK(contains(e["skipped"][0].get<std::string>(), "Blender is not at"));
        return;
    }
    CHECK(peers == 2);
    // The export (peer_cycles.cpp, cycles_scene.py) gives Cycles the same scene: the two
    // references agree in the red of the box's left half (the red wall) and the green of its
    // right half (the green wall), which a mirrored camera, a missing emitter or a light off by a
    // factor of pi would break. Each mean is over 288 pixels of 32 spp (Cycles: 2 x 16), whose
    // noise is a few per cent; the materials are Lambertian in both, so 10 % is noise alone.
    const json& refs = e["references"];
    const tp::RgbImage ours_ref = tp::load_rgb_image(refs["twinpath"]["files"][0]);
    tp::RgbImage peer_ref = tp::load_rgb_image(refs["peer"]["files"][0]);
    const tp::RgbImage other = tp::load_rgb_image(refs["peer"]["files"][1]);
    for (int c = 0; c < 3; ++c)
        for (size_t i = 0; i < peer_ref.pixels(); ++i)
            peer_ref.mean[c][i] = 0.5 * (peer_ref.mean[c][i] + other.mean[c][i]);
    for (const auto& [c, right] : {std::pair{0, false}, std::pair{1, true}}) {
        const double a = half_mean(ours_ref, c, right), b = half_mean(peer_ref, c, right);
        INFO("channel " << c << (right ? ", right half" : ", left half") << ": twinpath " << a
                        << ", Cycles " << b);
        CHECK(std::abs(a - b) <= 0.1 * a);
    }
}

} // namespace

TEST_CASE("lab peer at a tiny size writes a result that renders as well-formed files", "[lab]") {
    const std::string dir = tp::test::temp_dir("lab-peer");
    const std::string out = dir + "/out";
    const auto p = peer("--scenes cornell", out, dir + "/cache");
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    const json r = read_json(out + "/bench.json");
    CHECK(r["schema"] == "twinpath-bench/1");
    CHECK(r["sections"] == json::array({"peer"}));
    CHECK(r["title"] == "`local`: peer on the CPU");
    CHECK(contains(r["command"].get<std::string>(), "twinpath-lab peer --quick"));
    REQUIRE(r["scenes"].size() == 1);
    check_peer_files(out, r, p);
    check_efficiency(out, r);
}

TEST_CASE("lab peer says clearly when the peers are absent", "[lab]") {
    const std::string dir = tp::test::temp_dir("lab-no-peer");
    const std::string missing = dir + "/no/pathtracer";
    const auto p =
        peer("--peer-binary " + shell_quote(missing) + " --blender " + shell_quote(missing),
             dir + "/out", dir + "/cache");
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    CHECK(contains(p.out,
                   "skipping cornell peer: Embree's path tracer tutorial is not at " + missing));
    const json r = read_json(dir + "/out/bench.json");
    const json s = skipped_entry(r, "peer");
    REQUIRE(!s.is_null());
    CHECK(contains(s["reason"].get<std::string>(), "embree-tools"));
    CHECK(contains(read_file(dir + "/out/bench.md"), "- cornell peer: Embree's path tracer"));
    CHECK(contains(p.out, "skipping cornell time to error: Blender is not at " + missing));
}

TEST_CASE("lab peer rejects bad options with exit code 2 and writes nothing", "[lab]") {
    const std::string dir = tp::test::temp_dir("lab-peer-bad");
    for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
             {"--peer-spp 1", "--peer-spp must be at least 2"},
             {"--seed 2120155137", "is the references' seed"},
             {"--scenes no_such_scene", "'no_such_scene' is neither a benchmark scene"},
             {"--peer-threads 0", "--peer-threads"}}) {
        const auto p = peer(args, dir + "/out", dir + "/cache");
        INFO(args << "\n" << p.out);
        CHECK(p.exit_code == 2);
        CHECK(contains(p.out, message));
        CHECK(!fs::exists(dir + "/out"));
    }
}
