// Blender's Cycles (Debian package `blender`, run headless) as a peer of the efficiency table
// (peer_efficiency.h): the scene written as an OBJ of its world-space triangles, its textures as
// EXR files and a JSON description of materials, lights, environment, camera, film and path
// length, which cycles_scene.py turns into a Cycles scene inside Blender and renders to an EXR.
// Materials map to the nearest Cycles closures (cycles_scene.py): the two renderers' images are
// close, not equal, so each is judged against its own converged render.
#pragma once

#include "compare/rgb_image.h"
#include "scene/flatten.h"
#include "tools/lab/process.h"

#include <string>

namespace tp::lab {

// Why Cycles cannot render `scene` as twinpath does (an environment map, a light kind the export
// does not know), or "" when it can.
std::string cycles_unsupported(const FlatScene& scene);

// Writes scene.obj/.mtl, the textures, scene.json and cycles_scene.py into `dir`.
void write_cycles_scene(const FlatScene& scene, const std::string& dir);

struct CyclesRun {
    ProcessRun process; // the whole Blender process: start, import, BVH build, render, write
    RgbImage image;     // loaded when the process succeeded
    // Cycles' own clock (its progress lines, "Time:MM:SS.cc ... Sample k/N"): the first line
    // with k >= 1 samples done, and the line of the last sample; -1 where the log does not say.
    uint32_t first_samples = 0;
    double first_sample_s = -1, finished_s = -1;

    // Seconds per sample on Cycles' clock, after the first progress line; -1 if unknown.
    double time_per_spp(uint32_t spp) const {
        return first_sample_s >= 0 && finished_s > first_sample_s && spp > first_samples
                   ? (finished_s - first_sample_s) / double(spp - first_samples)
                   : -1;
    }
};

// Renders the scene written into `dir` with `spp` samples, Cycles' seed `seed`, on `threads`
// threads (0: every core), to `exr`; Blender's output goes to `log` (replaced).
CyclesRun run_cycles(const std::string& blender, const std::string& dir, const std::string& exr,
                     uint32_t spp, uint32_t seed, uint32_t threads, const std::string& log);

// `blender --version`'s first line ("Blender 3.4.1"), or "" when it does not run.
std::string cycles_version(const std::string& blender, const std::string& log);

} // namespace tp::lab
