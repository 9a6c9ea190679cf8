// The seeds of one verification (docs/debugging.md, "verify"). Every image verify compares has a
// seed of its own: two engines that draw the same numbers trace the same paths (shared/rng.h),
// and the two-sample test assumes independent images. The pilots have seeds of their own too,
// so that the sample counts chosen from them do not depend on the images' samples. The path
// logs of the triage have one seed on both engines: pathdiff replays one path on both.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace tp {

struct VerifySeeds {
    std::vector<uint32_t> pilot, image; // per engine
    uint32_t log = 0;                   // both engines' path logs
};

// From --seed S: a hash of (S, role) per seed, so that the runs of consecutive S share no seed;
// an engine with a seed of its own (`own`, the viewer's window) keeps it for its pilot and its
// image, and every other seed differs from it.
VerifySeeds verify_seeds(uint32_t seed, const std::vector<std::optional<uint32_t>>& own);

} // namespace tp
