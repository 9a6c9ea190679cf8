// Helpers the stress cases share: the reference scene and its variants, rendering with the
// NaN/Inf count, and the statistical comparison of two renders.
#pragma once

#include "stress/stress.h"

#include "scene/scene.h"
#include "util/clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace tp::stress {

// The reference scene: a Phong floor, a glossy smooth sphere resting on it, a box, an emissive
// quad facing down, a point light and a dim constant environment (so that no pixel is black),
// framed by a fixed camera. All sizes are O(1) metres around the origin.
Scene reference_scene(uint32_t image, uint32_t spp);
// The lights case's closed box (with its lights inside when `lit`) and the shading-normal
// furnace (render_cases.cpp), shared with the same-seed comparisons (twin_cases.cpp).
Scene closed_box_scene(const Scene& base, bool lit);
Scene smooth_furnace_scene(const Size& s, float rho, double& cos_min);

// Material helpers.
uint32_t add_material(Scene& s, const std::string& name, const Material& m);
Material phong(vec3 kd, vec3 ks = vec3(0.0f), float ns = 1.0f);
Material glass(float ior, vec3 tf = vec3(1.0f));
Material emitter(vec3 ke);
uint32_t add_mesh(Scene& s, Mesh m);
void add_object(Scene& s, const std::string& name, uint32_t mesh, uint32_t material,
                const glm::dmat4& transform);

struct Rendered {
    RenderResult r;
    uint64_t nonfinite_pixels = 0; // pixels of the film whose mean is NaN/Inf (0: dropped)
    uint64_t black_pixels = 0;     // pixels with a mean of exactly 0 in every channel
};
Rendered render(const Engine& e, const FlatScene& f, uint32_t seed);

// A group's reference render (seed `seed`); when it throws, `failed` gets the one case that
// says so and the group reports only that.
bool render_reference(const Engine& e, const Scene& base, uint32_t seed, const char* group,
                      const char* name, Rendered& ref, std::vector<CaseResult>& failed);

// compare's two-sample verdict (docs/compare.md) on two renders; `p` receives its p-value.
// Two independent renders (different seeds) of the same expectation are called different with
// probability alpha; the renders are deterministic, so a test is reproducible.
bool compare_consistent(const Rendered& a, const Rendered& b, double alpha, double& p);

// Counts NaN and Inf among a sampled BSDF's outputs into the case: the value, direction, weight
// and pdf of the sample and the value and pdf of the evaluated direction, two checks per output.
template <class BsdfOutput>
void count_nonfinite(CaseResult& c, const BsdfOutput& o) {
    auto count = [&c](float x) {
        c.nan += std::isnan(x);
        c.inf += std::isinf(x);
    };
    for (int ch = 0; ch < 3; ++ch) {
        count(o.sample_weight[ch]);
        count(o.f[ch]);
        count(o.sample_wi[ch]);
    }
    count(o.sample_pdf);
    count(o.pdf);
    c.checked += 2;
}

// Appends the render's NaN/Inf count (samples dropped by the engine, and film pixels that are
// not finite) to the case.
void count_nan(CaseResult& c, const Rendered& r);

// `variant` against `reference`: compare's two-sample test at alpha, no NaN/Inf, and no pixel
// black in the variant that is not black in the reference.
void expect_consistent(CaseResult& c, const Rendered& reference, const Rendered& variant,
                       double alpha);

CaseResult make_case(const std::string& group, const std::string& name, const Engine& e,
                     const std::string& expected);

// Runs `f(result)` with the time measured and a RuntimeError or InputError turned into a failed
// case that says what was thrown.
template <typename F>
CaseResult timed(CaseResult c, F&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    try {
        f(c);
    } catch (const std::exception& ex) {
        c.pass = false;
        c.measured += std::string(c.measured.empty() ? "" : "; ") + "threw: " + ex.what();
    }
    c.seconds = seconds_since(t0);
    return c;
}

inline double cmax(const glm::dvec3& v) {
    return std::max(v.x, std::max(v.y, v.z));
}
inline double cmin(const glm::dvec3& v) {
    return std::min(v.x, std::min(v.y, v.z));
}
inline float cmax(const vec3& v) {
    return std::max(v.x, std::max(v.y, v.z));
}

// Mean over the image of channel-averaged pixel means, and its standard error.
void image_mean(const Film& f, double& mean, double& se);

} // namespace tp::stress
