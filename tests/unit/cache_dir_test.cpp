// The one cache-directory rule (util/cache_dir.h): $TWINPATH_CACHE, else
// $XDG_CACHE_HOME/twinpath, else $HOME/.cache/twinpath, a set but empty variable counting as
// unset, and none without the three. Each test case runs in its own process (CTest), so the
// environment it sets stays there.
#include "util/cache_dir.h"

#include <catch2/catch.hpp>

#include <cstdlib>

namespace {

void set(const char* name, const char* value) {
    if (value)
        setenv(name, value, 1);
    else
        unsetenv(name);
}

void environment(const char* twinpath_cache, const char* xdg_cache_home, const char* home) {
    set("TWINPATH_CACHE", twinpath_cache);
    set("XDG_CACHE_HOME", xdg_cache_home);
    set("HOME", home);
}

} // namespace

TEST_CASE("the cache directory is $TWINPATH_CACHE, else $XDG_CACHE_HOME/twinpath, else "
          "~/.cache/twinpath",
          "[cache]") {
    environment("/c", "/x", "/h");
    CHECK(tp::cache_dir() == "/c");
    environment(nullptr, "/x", "/h");
    CHECK(tp::cache_dir() == "/x/twinpath");
    environment(nullptr, nullptr, "/h");
    CHECK(tp::cache_dir() == "/h/.cache/twinpath");
}

TEST_CASE("a cache variable that is set but empty counts as unset, and none gives no directory",
          "[cache]") {
    environment("", "/x", "/h");
    CHECK(tp::cache_dir() == "/x/twinpath");
    environment("", "", "/h");
    CHECK(tp::cache_dir() == "/h/.cache/twinpath");
    environment("", "", "");
    CHECK(tp::cache_dir().empty());
    environment(nullptr, nullptr, nullptr);
    CHECK(tp::cache_dir().empty());
}
