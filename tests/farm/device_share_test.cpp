// --device all without a device (vulkan_rt/renderer/sample_share.h, device_info.h): which devices a
// selector names, and how the samples are shared so that every sample is traced once and no
// device waits long at the end.
#include "util/error.h"
#include "vulkan_rt/device/device_info.h"
#include "vulkan_rt/renderer/sample_share.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

using namespace tp;

namespace {

DeviceInfo device(uint32_t index, const char* name, const char* type) {
    DeviceInfo d;
    d.index = index;
    d.name = name;
    d.type = type;
    d.pipeline_missing = "VK_KHR_ray_tracing_pipeline";
    return d;
}

// Devices that trace `rates[i]` samples per pixel per unit of time, each taking its next range
// when it finishes the last: an event simulation. Returns each device's finish time; `taken`
// gets every range.
std::vector<double> simulate(SampleShare& share, const std::vector<double>& rates,
                             std::vector<std::vector<SampleShare::Range>>& taken) {
    const size_t n = rates.size();
    std::vector<double> clock(n, 0.0), done(n, 0.0);
    std::vector<bool> finished(n, false);
    taken.assign(n, {});
    while (std::count(finished.begin(), finished.end(), false) > 0) {
        size_t d = 0; // the device that is free first
        for (size_t i = 0; i < n; ++i)
            if (!finished[i] && (finished[d] || clock[i] < clock[d])) d = i;
        const SampleShare::Range r = share.take(d, clock[d] > 0 ? done[d] / clock[d] : 0.0);
        if (r.count == 0) {
            finished[d] = true;
            continue;
        }
        taken[d].push_back(r);
        clock[d] += r.count / rates[d];
        done[d] += r.count;
    }
    return clock;
}

} // namespace

TEST_CASE("the shared ranges tile the render's samples, ascending on each device", "[farm]") {
    SampleShare share(100, 1000, 3);
    std::vector<std::vector<SampleShare::Range>> taken;
    simulate(share, {1.0, 2.5, 0.3}, taken);
    std::vector<SampleShare::Range> all;
    for (const auto& device : taken) {
        for (size_t i = 1; i < device.size(); ++i) CHECK(device[i].begin > device[i - 1].begin);
        all.insert(all.end(), device.begin(), device.end());
    }
    std::sort(all.begin(), all.end(), [](auto& a, auto& b) { return a.begin < b.begin; });
    uint32_t next = 100;
    for (const SampleShare::Range& r : all) {
        CHECK(r.begin == next);
        next = r.begin + r.count;
    }
    CHECK(next == 1100);
}

TEST_CASE("devices of different speeds finish within a sample of each other", "[farm]") {
    // Rates 1 : 3 : 0.25. The best possible end is N / (sum of rates), every device busy to
    // the end. Guided ranges end with single samples, so the devices finish apart by at most
    // the slowest device's time for its last range, one sample here: 1 / 0.25 = 4 units.
    const std::vector<double> rates = {1.0, 3.0, 0.25};
    SampleShare share(0, 4096, rates.size());
    std::vector<std::vector<SampleShare::Range>> taken;
    const std::vector<double> finish = simulate(share, rates, taken);
    const double ideal = 4096 / (1.0 + 3.0 + 0.25);
    const double last = *std::max_element(finish.begin(), finish.end());
    const double first = *std::min_element(finish.begin(), finish.end());
    for (size_t d = 0; d < rates.size(); ++d) {
        INFO("device " << d << " finished at " << finish[d] << ", ideal " << ideal);
        CHECK(taken[d].back().count / rates[d] <= 4.0 + 1e-9);
    }
    CHECK(last - first <= 4.0 + 1e-9);
    // The first ranges, before any rate is known, are equal (1/8 of an equal share each):
    // the slow device's costs it 4096 / 24 / 0.25 = 683 units, during which the others do
    // the rest; what it then takes is sized by its rate. The end is the ideal within that.
    CHECK(last <= ideal + 4.0 + 1e-9);
}

TEST_CASE("device all names every GPU, or the CPU device when it is alone", "[farm]") {
    const std::vector<DeviceInfo> mixed = {device(0, "llvmpipe", "cpu"),
                                           device(1, "NVIDIA H200", "discrete"),
                                           device(2, "NVIDIA H200", "discrete")};
    const std::vector<DeviceInfo> all = select_devices(mixed, "all");
    REQUIRE(all.size() == 2);
    CHECK(all[0].index == 1);
    CHECK(all[1].index == 2);
    CHECK(select_devices({device(0, "llvmpipe", "cpu")}, "all").size() == 1);
    const std::vector<DeviceInfo> list = select_devices(mixed, "2,llvm");
    REQUIRE(list.size() == 2);
    CHECK(list[0].index == 2);
    CHECK(list[1].index == 0);
    CHECK_THROWS_WITH(select_devices(mixed, "1,h200"), Catch::Contains("named twice"));
    CHECK_THROWS_AS(select_devices(mixed, "1,7"), InputError);
    CHECK(selects_several("all"));
    CHECK(selects_several("0,1"));
    CHECK_FALSE(selects_several("1"));
    CHECK(resolve_common_mode(std::nullopt, all) == VkMode::compute); // no pipeline caps set
}
