// Determinism (CPU backend): the same seed gives a bit-identical image for any thread
// count, since every random number is a function of (seed, pixel, sample, dimension) and each
// pixel's samples are added in order by one thread; a different seed gives a different image.
// Through the command line and the EXR file, as a user would compare them.
#include "image/exr_io.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>

namespace fs = std::filesystem;
using tp::test::run;
using tp::test::shell_quote;

namespace {

tp::ExrImage render(const std::string& scene, const fs::path& out, int threads, int seed) {
    // 40 x 24: tiles of 16 x 16 that do not divide the image.
    const auto r = run(tp::test::twinpath_bin() + " render " + scene +
                       " --width 40 --height 24 --spp 6 --threads " + std::to_string(threads) +
                       " --seed " + std::to_string(seed) + " -o " + shell_quote(out.string()));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    return tp::read_exr(out.string());
}

bool bit_identical(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

} // namespace

TEST_CASE(
    "the same seed gives a bit-identical EXR on 1 and 2 threads and another seed a different one",
    "[integration][determinism]") {
    const fs::path dir = tp::test::temp_dir("determinism");
    for (const char* scene : {"cornell", "spheres"}) {
        DYNAMIC_SECTION(scene) {
            const tp::ExrImage one = render(scene, dir / "one.exr", 1, 5);
            const tp::ExrImage two = render(scene, dir / "two.exr", 2, 5);
            const tp::ExrImage other = render(scene, dir / "other.exr", 2, 6);
            REQUIRE(one.channels.size() == two.channels.size());
            bool differs = false;
            for (const auto& [name, data] : one.channels) {
                CAPTURE(name);
                REQUIRE(two.has(name));
                CHECK(bit_identical(data, two.channel(name)));
                differs = differs || !bit_identical(data, other.channel(name));
            }
            CHECK(differs);
        }
    }
    fs::remove_all(dir);
}
