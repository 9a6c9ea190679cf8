// The frame of a benchmark run, which its sections fill: the options checked, the scenes
// loaded, the backends found, each section run on each scene, and one JSON result written
// (bench.json, schema twinpath-bench/1; docs/bench.md). `twinpath bench` runs its sections
// through it (run_bench.h), and so does the lab's peer comparison (tools/lab/peer_section.h).
#pragma once

#include "bench/backends.h"
#include "bench/options.h"
#include "scene/flatten.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace tp::bench {

// The state of one run: options, where things are, what ran and what did not.
struct BenchRun {
    BenchOptions o;
    std::string cache_dir, assets_dir;
    std::vector<Backend> backends;
    std::vector<Skip> skipped;
    bool failed = false; // a render failed at run time: exit code 3 once the result is written
    int step = 0, steps = 0;

    // "[bench 3/12] bunny vulkan/compute ladder" for the progress bar of the next step.
    std::string next_label(const std::string& what);

    // Records what was left out and why; it is said now on stderr and later in the result.
    void skip(const std::string& what, const std::string& reason);

    // Runs `f`; a run-time failure (device lost, out of memory) is recorded as skipped, and the
    // run goes on with what comes next.
    void guarded(const std::string& what, const std::function<void()>& f);
};

// One benchmark scene: its name, the scene as loaded, and the scene flattened at the run's
// image size and maximum depth.
struct BenchScene {
    std::string name;
    const Scene& scene;
    const FlatScene& flat;
};

// One section of the result: its name in the result's "sections", and what it adds to the
// record of each scene.
struct Section {
    std::string name;
    bool on_backends = false; // it renders on each of --backends, which are looked up first
    std::function<int(const BenchRun&)> steps; // progress-bar steps per scene
    std::function<void(BenchRun&, const BenchScene&, nlohmann::json& record)> run;
};

// `scene` at the run's image size and maximum depth.
FlatScene flatten_for_bench(Scene scene, const BenchOptions& o);

// Runs `sections` in order on each scene of o.scenes and writes o.out_dir/bench.json. Returns 0,
// or 3 when a render failed at run time (the result is written all the same); throws InputError
// for options no section can run with (the references' seed, no scenes), no cache directory, or
// when none of the scenes can be loaded, and then writes nothing. The options of a section are
// checked by its command first.
int run_sections(const BenchOptions& o, const std::vector<Section>& sections);

} // namespace tp::bench
