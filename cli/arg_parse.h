// Parsing of the command line's compound values ("X,Y,Z", "X,Y").
#pragma once

#include "shared/lang.h"
#include "util/error.h"

#include <string>

namespace tp {

// "1,2.5,-3" -> vec3; throws InputError naming the option.
vec3 parse_vec3(const std::string& option, const std::string& text);
// "12,34" -> two non-negative integers.
uvec2 parse_pixel(const std::string& option, const std::string& text);

} // namespace tp
