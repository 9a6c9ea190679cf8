// The debugging outputs of a render (docs/debugging.md): path logs of one pixel, AOVs and the
// debug views, as both backends return them, and their files: the path-log JSON that
// `twinpath pathdiff` reads and the AOV layers of the EXR.
#pragma once

#include "image/exr_io.h"
#include "shared/path_log.h"

#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

namespace tp {

// What a render is asked to record besides its image (RenderOptions::debug).
struct DebugRequest {
    uint32_t integrator = INTEGRATOR_PATH; // --integrator
    bool aov = false;                      // --aov: PixelAov of every pixel
    bool log = false;                      // --debug-log: PathVertex records of one pixel
    uint32_t pixel_x = 0, pixel_y = 0;     // --debug-pixel
    std::optional<uint32_t> sample;        // --debug-sample; none: every sample of the render

    // The samples a path log of a render of samples [begin, begin + spp) covers: [first, end).
    uint32_t first_sample(uint32_t begin) const { return sample ? *sample : begin; }
    uint32_t end_sample(uint32_t begin, uint32_t spp) const {
        return sample ? *sample + 1u : begin + spp;
    }
    // Anything that needs the debug variant of the path loop (cpu: its instantiation; Vulkan: the
    // TP_DEBUG_SHADER module).
    bool active() const { return integrator != INTEGRATOR_PATH || aov || log; }
};

// What the render recorded (RenderResult::debug).
struct DebugOutput {
    std::vector<PathVertex> records; // sample by sample, each path's vertices in order
    uint64_t dropped = 0;            // records beyond the GPU buffer's capacity
    std::vector<PixelAov> aovs;      // width x height, row-major, when requested
};

// Upper bound of records per logged sample (the GPU buffer is sized from it).
inline uint32_t path_log_records_per_sample(uint32_t max_depth) {
    return max_depth + 2u;
}

// --integrator NAME -> INTEGRATOR_*; InputError for an unknown name.
uint32_t integrator_from_name(const std::string& name);
const char* integrator_name(uint32_t integrator);

// What a path log records about the render it came from (pathdiff checks pixel, seed, size).
struct PathLogInfo {
    std::string backend, mode, device, scene;
    uint32_t seed = 0, width = 0, height = 0, spp = 0, max_depth = 0, min_depth = 0;
    std::string sampler; // render/sampler.h
    uint32_t pixel_x = 0, pixel_y = 0;
    uint64_t dropped = 0;
    // FlatScene::origin, the camera's eye: the engines, and the log, record positions relative to
    // it (docs/debugging.md).
    glm::dvec3 origin{0.0};
};

// The path log as JSON (docs/debugging.md, "Path log format"), and written to a file.
nlohmann::json path_log_json(const PathLogInfo& info, const std::vector<PathVertex>& records);
void write_path_log(const std::string& path, const PathLogInfo& info,
                    const std::vector<PathVertex>& records);

// Adds the AOV layers albedo.R/G/B, normal.X/Y/Z, depth.Z, id.instance, id.material.
void add_aov_layers(ExrImage& img, const std::vector<PixelAov>& aovs);

} // namespace tp

namespace tp {

// The fields of a path-log vertex in the order the path loop computes them, which is the
// order `pathdiff` checks them in, with the tolerance class each is compared under.
enum class FieldKind {
    Exact,       // integers, names and the random numbers (the same hash on both sides)
    Geometry,    // positions and distances: relative to max(1, |value|)
    Direction,   // unit vectors, barycentrics, cosines: absolute
    Radiometric, // pdfs, BRDF values, weights, radiance: relative
};
struct PathLogField {
    const char* name;
    FieldKind kind;
};
const std::vector<PathLogField>& path_log_fields();
const char* field_kind_name(FieldKind k);

} // namespace tp
