// An image texture or environment map in memory: linear RGB texels, rows top to bottom.
#pragma once

#include "shared/lang.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tp {

struct Texture {
    std::string name;
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<vec3> texels; // linear RGB, rows top to bottom
};

} // namespace tp
