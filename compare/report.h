// `--report DIR`: the two images, their difference, the signed per-pixel z map and the tile z
// map as PNG files, and an index.html that shows them side by side with the numbers. The page
// records, once loaded, whether every image decoded (data-images-loaded="k/n" on <body>), so
// that a headless browser can check it (tests/compare/test_report.cpp).
#pragma once

#include "compare/compare.h"

#include <string>

namespace tp {

void write_report(const std::string& dir, const CompareResult& r, const RgbImage& a,
                  const RgbImage& b);

} // namespace tp
