// Split renders on the Vulkan engine (lavapipe in CI): --sample-offset shifts the sample index
// the shaders hash, and parts merge into one render.
#include "image/exr_io.h"
#include "split_check.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

using tp::test::render_part;

TEST_CASE("--sample-offset shifts the samples of the Vulkan compute engine", "[farm][gpu]") {
    tp::test::check_offset_shifts_samples(tp::test::temp_dir("offset-vk"),
                                          "--backend vulkan --vk-mode compute");
}

TEST_CASE("Vulkan parts tiling [0, 2N) merge into the 2N render", "[farm][gpu]") {
    const std::string dir = tp::test::temp_dir("merge-vk");
    const std::string vk = "--backend vulkan --vk-mode compute ";
    const std::string a = render_part(dir, "a.exr", vk + "--spp 3");
    const std::string b = render_part(dir, "b.exr", vk + "--spp 3 --sample-offset 3");
    const std::string single = render_part(dir, "single.exr", vk + "--spp 6");
    tp::test::check_merge_equals_single(dir, {a, b}, single);
    std::filesystem::remove_all(dir);
}
