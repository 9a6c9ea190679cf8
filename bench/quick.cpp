#include "bench/quick.h"

namespace tp::bench {

void apply_quick(BenchOptions& o, const std::function<bool(const std::string&)>& given) {
    const auto unset = [&](const char* option) { return !given(option); };
    if (unset("--width")) o.width = 24;
    if (unset("--height")) o.height = 24;
    if (unset("--max-spp")) o.max_spp = 4;
    if (unset("--ref-spp")) o.ref_spp = 32;
    if (unset("--scenes")) o.scenes = {"cornell"};
    if (unset("--table-depths")) o.table_depths = {1, 2};
    if (unset("--table-spp")) o.table_spp = {1, 4};
    if (unset("--table-fixed-spp")) o.table_fixed_spp = 2;
    if (unset("--table-fixed-depth")) o.table_fixed_depth = 2;
    if (unset("--peer-spp")) o.peer_spp = 2;
    if (unset("--sizes-list")) o.sizes_list = {"8x8", "16x16"};
    if (unset("--sizes-time")) o.sizes_time_s = 0.02;
    if (unset("--sizes-rounds")) o.sizes_rounds = 1;
    if (unset("--peer-budget")) o.peer_budget_s = 0.2;
}

} // namespace tp::bench
