#include "bench/reference.h"

#include "bench/options.h"
#include "bench/renderer_version.h"
#include "cpu_ref/cpu_renderer.h"
#include "image/exr_io.h"
#include "render/render_header.h"
#include "scene/scene_hash.h"
#include "util/cache_dir.h"
#include "util/error.h"

#include <fmt/format.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace tp::bench {
namespace {

constexpr const char* kKeyAttribute = "twinpath:bench_key";

} // namespace

std::string resolve_cache_dir(const std::string& option) {
    if (!option.empty()) return option;
    const std::string dir = cache_dir();
    if (dir.empty())
        input_error("no cache directory for the references: give --cache DIR, or set "
                    "TWINPATH_CACHE, XDG_CACHE_HOME or HOME");
    return dir;
}

Reference reference_for(const FlatScene& scene, const std::string& name, uint32_t spp,
                        const std::string& cache_dir, const std::function<void(double)>& progress) {
    FlatScene s = scene;
    s.spp = spp;
    s.params.seed = kReferenceSeed; // what render_cpu sets from RenderOptions::seed
    Reference ref;
    ref.key = fmt::format("{:016x}-{}", render_inputs_hash(s), renderer_version());
    ref.spp = spp;
    const fs::path dir = fs::path(cache_dir) / "references";
    ref.file = (dir / fmt::format("{}-{}.exr", fs::path(name).stem().string(), ref.key)).string();

    if (fs::exists(ref.file)) {
        const ExrImage img = read_exr(ref.file);
        const auto key = img.strings.find(kKeyAttribute);
        if (key != img.strings.end() && key->second == ref.key) {
            ref.image = rgb_image_from_exr(img, ref.file);
            ref.cached = true;
            ref.render_s =
                img.reals.count(header::kRenderTime) ? img.reals.at(header::kRenderTime) : 0.0;
            return ref;
        }
    }

    RenderOptions opt;
    opt.seed = kReferenceSeed;
    opt.progress = progress;
    const RenderResult r = render_cpu(s, opt);
    ExrImage img = render_exr(r, s, opt);
    img.strings[kKeyAttribute] = ref.key;
    img.strings[header::kScene] = name;
    fs::create_directories(dir);
    write_exr(ref.file, img);
    ref.image = rgb_image_from_exr(img, ref.file);
    ref.render_s = r.stats.wall_time_s;
    return ref;
}

} // namespace tp::bench
