// Tile-parallel progressive rendering on the CPU: passes of whole samples over the image,
// each pass split into 16x16 tiles that TBB spreads over the threads. Every pixel's samples
// are added to the film in sample order by one thread, and every random number depends only
// on (seed, pixel, sample, dimension), so the image is bit-identical for any thread count.
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"

namespace tp {

RenderResult render_cpu(const FlatScene& scene, const RenderOptions& options);

} // namespace tp
