// The glTF material's furnace, shared by the CPU render test
// (tests/integration/pbr_furnace_test.cpp) and the Vulkan one (tests/gpu/pbr_render_test.cpp): a
// flat surface under a constant white environment, rendered at max depth 1, shows its directional
// albedo. The scene is a JSON file as a user writes it (docs/scene-format.md): a quad 2000 m wide
// with a `"type": "pbr"` material, a camera 10 m away with a field of view of 0.5 degrees looking
// at its centre from `view_degrees` off the normal (its pixels see the surface within 0.25 degrees
// of that angle), environment radiance 1 and no roulette. With max depth 1 a path is the camera
// ray, next-event estimation to the environment and one BSDF-sampled ray that escapes (MIS between
// them), so a pixel's expectation is the integral of f |cos| over the sphere: the albedo (plus the
// Dirac lobes' weights in the smooth limit); transmitted light escapes below the quad and sees
// radiance 1 too. The expected value is pbr_reference.h's quadrature.
#pragma once

#include "support/pbr_reference.h"

#include <string>
#include <utility>
#include <vector>

namespace tp::test::pbr {

struct FurnaceCase {
    std::string name;
    Params p;            // the material as the path meets it (ior relative, 1/ior from inside)
    double view_degrees; // the camera's angle from the surface normal
    bool from_below;     // the camera under the quad: a volume boundary met from inside
    bool on_gpu; // also in the Vulkan test (a subset: lavapipe builds a pipeline per render)

    // Light arrives through the surface, and next-event estimation samples the environment
    // below it (integrator.h weighs it by |dot(ns, wi)|); checked by test cases of their own.
    bool transmits() const { return p.transmission > 0.0 && p.metallic < 1.0; }
};

std::vector<FurnaceCase> furnace_cases();

// Writes the scene of case c into dir and returns its path.
std::string write_furnace_scene(const FurnaceCase& c, const std::string& dir);

// The view direction of case c in the surface's local frame (N = +z).
glm::dvec3 furnace_view(const FurnaceCase& c);

struct ImageMean {
    glm::dvec3 mean{0.0};
    glm::dvec3 se{0.0}; // from the film's variance of each pixel mean (pixels are independent)
};
ImageMean image_mean(const std::string& exr_path);

// ---- the debug outputs' scene -----------------------------------------------------------------
// A small PBR scene for path logs and AOVs: a floor with base colour (0.2, 0.4, 0.6), metallic
// 0.25, roughness 0.45, transmission 0.3 and alpha 0.6 (alpha_mode "mask" at the default cutoff
// 0.5: there; or "blend"), under a rough gold ball (metallic 1, roughness 0.3), a point light and
// a dim environment, 16 x 16. `textured`: the floor's metallic-roughness texture is a checker
// (G: roughness x 0.8 or 0.2, B: metallic x 0.5 or 0.1), so the fields show textures applied.
// (Lavapipe compiles the debug shader variant of a textured PBR scene in about a minute, of an
// untextured one in seconds: the GPU tests take the untextured scene.)
std::string write_debug_scene(const std::string& dir, bool textured, const char* alpha_mode);

// Checks the material fields of every hit of a path log (render --debug-log) of that scene: the
// floor's as above (its roughness and metallic within the checker's range, or the factors), the
// ball's factors. Returns the hits on the floor and on the ball.
std::pair<size_t, size_t> check_debug_log(const std::string& log, bool textured);

// Checks the pbr.roughness and pbr.metallic AOV layers (render --aov all) of that scene: the
// floor's and the ball's values as above (with a texture, both checks in view), 0 where no
// surface is hit.
void check_debug_aovs(const std::string& exr, bool textured);

} // namespace tp::test::pbr
