// Rounding up to a multiple, for the alignments Vulkan states as plain numbers (shader binding
// table, scratch buffers). Any positive alignment, not only powers of two.
#pragma once

#include <cstdint>

namespace tp {

constexpr uint64_t align_up(uint64_t value, uint64_t alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

} // namespace tp
