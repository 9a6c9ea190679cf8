#include "compare/quality.h"

#ifdef TWINPATH_WITH_OIIO
#include "compare/display.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <limits>
#endif

namespace tp {

#ifdef TWINPATH_WITH_OIIO
std::optional<double> display_psnr(const RgbImage& test, const RgbImage& ref,
                                   float exposure_stops) {
    std::vector<float> a = display_srgb(test, exposure_stops);
    std::vector<float> b = display_srgb(ref, exposure_stops);
    const OIIO::ImageSpec spec(test.width, test.height, 3, OIIO::TypeDesc::FLOAT);
    const OIIO::ImageBuf ia(spec, a.data()), ib(spec, b.data());
    // `error` also reports values beyond the fail threshold; none is wanted, so it is huge.
    const float never = std::numeric_limits<float>::max();
    const OIIO::ImageBufAlgo::CompareResults r = OIIO::ImageBufAlgo::compare(ia, ib, never, never);
    if (r.error) return std::nullopt;
    return r.PSNR;
}
#else
std::optional<double> display_psnr(const RgbImage&, const RgbImage&, float) {
    return std::nullopt;
}
#endif

} // namespace tp
