// The automatic exposure of a preview (render --png, view, compare's report): the one that maps
// the 99th percentile of the pixels' largest channel to 1, so that a few fireflies or light
// sources do not darken the rest and a dim scene is not shown black. In stops (a factor 2^e).
#pragma once

#include <vector>

namespace tp {

// `peaks`: each pixel's largest channel (reordered by the call). 0 where the percentile is 0 or
// not finite (a black image), clamped to +-30 stops.
float auto_exposure_stops(std::vector<double>& peaks);

// The same for an image given as its R, G and B planes (equal sizes).
float auto_exposure_stops(const std::vector<float>& r, const std::vector<float>& g,
                          const std::vector<float>& b);

} // namespace tp
