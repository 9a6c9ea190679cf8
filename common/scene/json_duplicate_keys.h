// JSON allows an object to repeat a key and nlohmann keeps the last value, so an invalid earlier
// value would never be checked: a scene file with a repeated key is an input error instead.
#pragma once

#include <string>

namespace tp {

// Throws InputError naming `path`, the key and the lines of both occurrences when an object of
// the (well-formed) JSON `text` has a key twice.
void reject_duplicate_keys(const std::string& path, const std::string& text);

} // namespace tp
