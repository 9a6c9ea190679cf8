#include "vulkan_rt/pipeline_mode/sbt_layout.h"

#include "util/error.h"
#include "vulkan_rt/device/align.h"

#include <cstring>

namespace tp {

SbtLayout sbt_layout(const SbtProperties& p, uint32_t miss_count, uint32_t hit_count) {
    const uint64_t record = align_up(p.handle_size, p.handle_alignment);
    if (record > p.max_stride)
        runtime_error("the shader binding table needs a record stride of {} bytes; the device "
                      "allows {}",
                      record, p.max_stride);
    SbtLayout l{};
    l.handle_size = p.handle_size;
    l.miss_count = miss_count;
    l.hit_count = hit_count;
    // The ray-generation region is one record; its stride is padded to the base alignment so
    // that the next region starts aligned (its size must equal its stride).
    const uint64_t raygen = align_up(record, p.base_alignment);
    l.raygen = {0, raygen, raygen};
    l.miss = {l.raygen.offset + l.raygen.size, record,
              align_up(uint64_t(miss_count) * record, p.base_alignment)};
    l.hit = {l.miss.offset + l.miss.size, record,
             align_up(uint64_t(hit_count) * record, p.base_alignment)};
    l.bytes = l.hit.offset + l.hit.size;
    return l;
}

std::vector<uint8_t> sbt_table(const SbtLayout& l, const std::vector<uint8_t>& handles) {
    std::vector<uint8_t> table(l.bytes, 0);
    const uint8_t* h = handles.data();
    auto put = [&](const SbtRegion& r, uint32_t count) {
        for (uint32_t i = 0; i < count; ++i, h += l.handle_size)
            std::memcpy(&table[r.offset + i * r.stride], h, l.handle_size);
    };
    put(l.raygen, 1);
    put(l.miss, l.miss_count);
    put(l.hit, l.hit_count);
    return table;
}

uint64_t sbt_placement(uint64_t address, uint32_t base_alignment) {
    return align_up(address, base_alignment) - address;
}

} // namespace tp
