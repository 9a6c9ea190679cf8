// The device memory a context holds (vulkan_rt/device/memory_tally.h): every Buffer and Image
// adds its allocation while it lives, and the peak is the most held at once.
#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/image.h"
#include "vulkan_rt/device/memory_tally.h"

#include <catch2/catch.hpp>

#include <optional>
#include <utility>

using namespace tp;

TEST_CASE("the memory tally keeps what is held now and the most held at once", "[gpu]") {
    MemoryTally t;
    t.add(100);
    t.add(50);
    t.remove(100);
    CHECK(t.held() == 50);
    CHECK(t.peak() == 150);
    t.restart_peak();
    CHECK(t.peak() == 50);
    t.add(20);
    CHECK(t.peak() == 70);
}

TEST_CASE("a context's buffers and images add their device memory while they live", "[gpu]") {
    const VulkanContext ctx("");
    MemoryTally& tally = ctx.memory_tally();
    const uint64_t before = tally.held();
    const VkDeviceSize mib = VkDeviceSize(1) << 20;
    {
        Buffer buffer(ctx, mib, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
        CHECK(tally.held() >= before + mib);
        std::optional<Image> image(std::in_place, ctx, 256u, 256u, VK_FORMAT_R8G8B8A8_UNORM);
        CHECK(tally.held() >= before + mib + 256 * 256 * 4);
        const uint64_t both = tally.held();
        image.reset();
        CHECK(tally.held() < both);
        const uint64_t one = tally.held();
        const Buffer moved = std::move(buffer); // the allocation moves, and is counted once
        CHECK(tally.held() == one);
        CHECK(tally.peak() >= both);
    }
    CHECK(tally.held() == before);
}
