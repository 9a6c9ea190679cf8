// 64-bit FNV-1a (util/fnv1a.h) against the published test vectors (Fowler, Noll & Vo's
// reference code, test_fnv.c), and the piecewise hash against the whole one.
#include "util/fnv1a.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <string>

TEST_CASE("FNV-1a 64 gives the reference values", "[fnv]") {
    const auto hash = [](const char* s) { return tp::fnv1a64(s, std::strlen(s)); };
    CHECK(hash("") == 0xcbf29ce484222325ull);
    CHECK(hash("a") == 0xaf63dc4c8601ec8cull);
    CHECK(hash("foobar") == 0x85944171f73967e8ull);
}

TEST_CASE("FNV-1a fed piece by piece equals the hash of the whole", "[fnv]") {
    const std::string whole = "twinpath";
    tp::Fnv1a h;
    h.bytes(whole.data(), 4);
    h.bytes(whole.data() + 4, whole.size() - 4);
    CHECK(h.get() == tp::fnv1a64(whole.data(), whole.size()));
    CHECK(tp::fnv1a64(whole.data() + 4, 4, tp::fnv1a64(whole.data(), 4)) == h.get());
}
