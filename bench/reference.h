// The reference image of a benchmark scene: a high-spp CPU render (the project's oracle),
// cached on disk under a key made of the flattened scene's hash and the renderer version, so
// it is rendered again exactly when the scene, the render settings or the integrator sources
// change.
#pragma once

#include "compare/rgb_image.h"
#include "scene/flatten.h"

#include <functional>
#include <string>

namespace tp::bench {

struct Reference {
    RgbImage image;
    std::string file;    // the cached OpenEXR
    std::string key;     // <scene hash>-<renderer version>
    bool cached = false; // read from the cache rather than rendered now
    double render_s = 0; // how long the CPU took to render it (recorded in the file)
    uint32_t spp = 0;
};

// The cache directory: `option` (--cache) if given, else the project's (util/cache_dir.h);
// InputError when there is none, since the references need a place.
std::string resolve_cache_dir(const std::string& option);

// `scene` at the benchmark's size and depths; the reference is rendered from it with `spp`
// samples, kReferenceSeed and all CPU threads. `name` names the cache file.
Reference reference_for(const FlatScene& scene, const std::string& name, uint32_t spp,
                        const std::string& cache_dir, const std::function<void(double)>& progress);

} // namespace tp::bench
