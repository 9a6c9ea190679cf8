// Checks every case a stress function returns and prints its line (with its NaN/Inf counts)
// into the test log, so that a CTest run reports them all.
#pragma once

#include "stress/stress.h"

#include <catch2/catch.hpp>

#include <cstdio>

namespace tp::stress {

inline void require_all(const std::vector<CaseResult>& cases) {
    REQUIRE(!cases.empty());
    for (const CaseResult& c : cases) {
        std::printf("%s\n", describe(c).c_str());
        INFO(describe(c));
        CHECK(!c.skipped);
        CHECK(c.nan == 0);
        CHECK(c.inf == 0);
        CHECK(c.pass);
    }
}

} // namespace tp::stress
