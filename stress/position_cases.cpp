// The position group: a scene moved together with its camera renders the same
// image wherever it sits. The description keeps positions in double and flatten() rounds to
// float only after subtracting the camera's eye (scene/flatten.h, FlatScene::origin), so when
// every number of the description survives the move exactly ((x + d) - d == x), both scenes
// flatten to the same floats and one seed gives the same image bit for bit on every engine. The
// reference scene is moved twice: by its objects' translations (a JSON scene's transforms), and
// as world-space vertices (an OBJ file's).
#include "stress/common.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>

namespace tp::stress {
namespace {

// Moves positions by d, counting those that do not survive the move exactly.
struct Mover {
    glm::dvec3 d;
    uint64_t inexact = 0;
    void operator()(glm::dvec3& x) {
        if ((x + d) - d != x) ++inexact;
        x += d;
    }
};

// `s` moved by m.d: its camera, point lights and either every object's translation or, with
// `vertices`, every mesh's vertices (a scene whose meshes are world-space, one per object).
Scene moved(Scene s, Mover& m, bool vertices) {
    if (vertices) {
        for (Mesh& mesh : s.meshes)
            for (glm::dvec3& p : mesh.positions) m(p);
    } else {
        for (Object& o : s.objects) {
            glm::dvec3 t(o.transform[3]);
            m(t);
            o.transform[3] = glm::dvec4(t, 1.0);
        }
    }
    m(s.camera.eye);
    m(s.camera.target);
    for (LightDesc& l : s.lights)
        if (l.type == LIGHT_POINT) m(l.position);
    return s;
}

// The scene as an OBJ file holds it: one mesh per object with its vertices in world space (M p
// + T in double) and identity transforms. The vertices are put on the grid of 2^-24 (a move of
// at most 3e-8): every coordinate here is below 8, so on that grid it has at most 27
// significant bits and a move by up to 2^26 (6.7e7) keeps it exact in double's 53.
Scene baked(const Scene& s) {
    Scene out = s;
    out.meshes.clear();
    out.objects.clear();
    for (const Object& o : s.objects) {
        Mesh m = s.meshes[o.mesh];
        for (glm::dvec3& p : m.positions)
            p = glm::round(glm::dvec3(o.transform * glm::dvec4(p, 1.0)) * 0x1p24) * 0x1p-24;
        const glm::dmat3 normal_to_world = glm::inverseTranspose(glm::dmat3(o.transform));
        for (vec3& n : m.normals) n = vec3(glm::normalize(normal_to_world * glm::dvec3(n)));
        Object w = o;
        w.mesh = add_mesh(out, std::move(m));
        w.transform = glm::dmat4(1.0);
        out.objects.push_back(w);
    }
    return out;
}

// `moved` against `origin`, both rendered with one seed: every pixel's mean and variance equal,
// no NaN/Inf, and compare's verdict (consistent, as it must be for equal images).
void expect_same_image(CaseResult& c, const Rendered& origin, const Rendered& moved,
                       uint64_t inexact, double alpha) {
    count_nan(c, origin);
    count_nan(c, moved);
    const Film& a = origin.r.film;
    const Film& b = moved.r.film;
    uint64_t differ = 0;
    double worst = 0.0;
    for (uint32_t p = 0; p < a.width() * a.height(); ++p)
        for (int ch = 0; ch < 3; ++ch) {
            const double d = std::abs(a.mean(p)[ch] - b.mean(p)[ch]);
            worst = std::max(worst, d);
            differ += d != 0.0 || a.variance_of_mean(p)[ch] != b.variance_of_mean(p)[ch];
        }
    double p = 0.0;
    const bool consistent = compare_consistent(origin, moved, alpha, p);
    c.pass = inexact == 0 && differ == 0 && consistent && c.nan == 0;
    c.measured =
        fmt::format("{} of {} pixel-channels differ (largest |difference| {:.3g}); compare "
                    "p = {:.3g} ({}); {} positions moved inexactly",
                    differ, 3 * a.width() * a.height(), worst, p,
                    consistent ? "consistent" : "different", inexact);
}

} // namespace

std::vector<CaseResult> position_cases(const Engine& e, const Size& s) {
    std::vector<CaseResult> out;
    const uint32_t seed = 7;
    for (const bool vertices : {false, true}) {
        const Scene base =
            vertices ? baked(reference_scene(s.image, s.spp)) : reference_scene(s.image, s.spp);
        const char* how = vertices ? "as world-space vertices" : "by its objects' translations";
        Rendered origin;
        if (!render_reference(e, base, seed, "position",
                              vertices ? "world-space vertices at the origin" : "at the origin",
                              origin, out))
            return out;
        const std::pair<const char*, double> distances[] = {
            {"1e2", 1e2}, {"1e4", 1e4}, {"1e6", 1e6}};
        for (const auto& [name, d] : distances) {
            const double distance = d; // a structured binding is not captured before C++20
            out.push_back(timed(
                make_case("position", fmt::format("moved {} {}", name, how), e,
                          "the image at the origin for the same seed: every pixel equal, no "
                          "NaN/Inf"),
                [&](CaseResult& c) {
                    Mover m{glm::dvec3(distance, -distance, distance)};
                    const Scene far = moved(base, m, vertices);
                    expect_same_image(c, origin, render(e, flatten(far), seed), m.inexact, s.alpha);
                }));
        }
    }
    return out;
}

} // namespace tp::stress
