// An image-quality metric from a library rather than from this project: PSNR through
// OpenImageIO's ImageBufAlgo::compare, on the sRGB display images (display.h), where the peak
// value 1 that PSNR presumes is meaningful. Absent in builds without OpenImageIO (the GPU
// bundle, TWINPATH_WITH_OIIO off).
#pragma once

#include "compare/rgb_image.h"

#include <optional>

namespace tp {

std::optional<double> display_psnr(const RgbImage& test, const RgbImage& ref, float exposure_stops);

} // namespace tp
