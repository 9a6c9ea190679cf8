// Parsing of the command line's compound values ("X,Y,Z", "X,Y").
#pragma once

#include "shared/lang.h"
#include "util/error.h"

#include <CLI/CLI.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace tp {

// "1,2.5,-3" -> three finite numbers, in double (--eye and --target are positions, which the
// scene keeps in double: scene/scene.h); throws InputError naming the option.
glm::dvec3 parse_xyz(const std::string& option, const std::string& text);
// "12,34" -> two non-negative integers.
uvec2 parse_pixel(const std::string& option, const std::string& text);

// "1%" or "0.01" -> a relative amount strictly between 0 and 1; throws InputError naming the
// option.
double parse_relative_bias(const std::string& option, const std::string& text);

// A CLI11 check for a real-valued option: a number in [lo, hi], which NaN is not (CLI::Range
// and CLI::NonNegativeNumber compare with < and >, and let NaN through).
CLI::Validator number_in(double lo, double hi);

} // namespace tp
