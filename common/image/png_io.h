// 8-bit PNG output through libpng (every build, the GPU bundle too) and the sRGB preview
// tone mapping used for `--png` and compare reports.
#pragma once

#include "shared/tonemap.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tp {

// rgb: width * height * 3 bytes, rows top to bottom. Written through write_output_file
// (util/output_file.h): no partial file, a device written in place. Throws RuntimeError.
void write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb);

// Linear radiance to display, pixel by pixel as the viewer's display pass (shared/tonemap.h,
// display_srgb8): non-finite values become magenta so they cannot hide.
std::vector<uint8_t> tonemap_srgb8(const std::vector<float>& r, const std::vector<float>& g,
                                   const std::vector<float>& b, float exposure_stops);

} // namespace tp
