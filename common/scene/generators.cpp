#include "scene/generators.h"

#include "shared/math.h"
#include "shared/texture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <utility>

namespace tp {

Mesh make_icosphere(uint32_t subdivisions, bool inward) {
    // The 12 vertices (0, +-1, +-phi) and cyclic permutations; 20 faces counter-clockwise seen
    // from outside.
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    std::vector<uvec3> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                            {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                            {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                            {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (auto& p : v) p = glm::normalize(p);
    for (uint32_t s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint;
        auto mid = [&](uint32_t a, uint32_t b) {
            auto key = std::minmax(a, b);
            auto it = midpoint.find(key);
            if (it != midpoint.end()) return it->second;
            v.push_back(glm::normalize(v[a] + v[b]));
            return midpoint[key] = uint32_t(v.size() - 1);
        };
        std::vector<uvec3> next;
        next.reserve(f.size() * 4);
        for (const auto& tri : f) {
            uint32_t a = mid(tri.x, tri.y), b = mid(tri.y, tri.z), c = mid(tri.z, tri.x);
            next.push_back({tri.x, a, c});
            next.push_back({tri.y, b, a});
            next.push_back({tri.z, c, b});
            next.push_back({a, b, c});
        }
        f.swap(next);
    }
    Mesh m;
    m.name = inward ? "icosphere_inward" : "icosphere";
    m.positions.assign(v.begin(), v.end());
    m.normals.resize(v.size());
    m.uvs.resize(v.size());
    for (size_t i = 0; i < v.size(); ++i) {
        m.normals[i] = inward ? -v[i] : v[i];
        m.uvs[i] = uv_to_image(direction_to_latlong(v[i]));
    }
    m.triangles = f;
    if (inward)
        for (auto& tri : m.triangles) std::swap(tri.y, tri.z);
    return m;
}

Mesh make_quad() {
    Mesh m;
    m.name = "quad";
    m.positions = {{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}};
    m.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

Mesh make_box() {
    Mesh m;
    m.name = "box";
    // Each face: a corner and two edge directions whose cross product points outwards. Every
    // face starts at its (-, -) corner and is split along the diagonal to (+, +), so a copy
    // moved by the box's width along an axis touches it with the same two triangles, reversed:
    // touching dielectric boxes are then merged into one interface (dielectric_interfaces.h).
    const std::array<std::array<vec3, 3>, 6> faces = {{
        {{{1, -1, -1}, {0, 2, 0}, {0, 0, 2}}},  // +X
        {{{-1, -1, -1}, {0, 0, 2}, {0, 2, 0}}}, // -X
        {{{-1, 1, -1}, {0, 0, 2}, {2, 0, 0}}},  // +Y
        {{{-1, -1, -1}, {2, 0, 0}, {0, 0, 2}}}, // -Y
        {{{-1, -1, 1}, {2, 0, 0}, {0, 2, 0}}},  // +Z
        {{{-1, -1, -1}, {0, 2, 0}, {2, 0, 0}}}, // -Z
    }};
    for (const auto& face : faces) {
        const uint32_t base = uint32_t(m.positions.size());
        const vec3 o = face[0], du = face[1], dv = face[2];
        m.positions.insert(m.positions.end(), {o, o + du, o + du + dv, o + dv});
        m.triangles.push_back({base, base + 1, base + 2});
        m.triangles.push_back({base, base + 2, base + 3});
    }
    return m;
}

Texture make_checker_texture(uint32_t size, uint32_t checks, vec3 a, vec3 b) {
    std::vector<vec3> texels(size_t(size) * size);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const uint32_t cx = x * checks / size, cy = y * checks / size;
            texels[size_t(y) * size + x] = ((cx + cy) & 1u) ? b : a;
        }
    return texture_from_linear_rgb(size, size, texels);
}

namespace {
// Perlin's improved noise (2002) in 2D on a lattice that wraps every `period` cells.
struct GradientNoise {
    std::array<int, 512> perm{};
    explicit GradientNoise(uint32_t seed) {
        std::array<int, 256> p;
        std::iota(p.begin(), p.end(), 0);
        std::mt19937 rng(seed);
        std::shuffle(p.begin(), p.end(), rng);
        for (int i = 0; i < 512; ++i) perm[i] = p[i & 255];
    }
    static float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }
    float grad(int h, float x, float y) const {
        switch (h & 7) {
        case 0:
            return x + y;
        case 1:
            return -x + y;
        case 2:
            return x - y;
        case 3:
            return -x - y;
        case 4:
            return x;
        case 5:
            return -x;
        case 6:
            return y;
        default:
            return -y;
        }
    }
    int hash(int x, int y, int period) const {
        x = ((x % period) + period) % period;
        y = ((y % period) + period) % period;
        return perm[perm[x & 255] + (y & 255)];
    }
    float operator()(float x, float y, int period) const {
        const int xi = int(std::floor(x)), yi = int(std::floor(y));
        const float xf = x - float(xi), yf = y - float(yi);
        const float u = fade(xf), v = fade(yf);
        const float n00 = grad(hash(xi, yi, period), xf, yf);
        const float n10 = grad(hash(xi + 1, yi, period), xf - 1, yf);
        const float n01 = grad(hash(xi, yi + 1, period), xf, yf - 1);
        const float n11 = grad(hash(xi + 1, yi + 1, period), xf - 1, yf - 1);
        return glm::mix(glm::mix(n00, n10, u), glm::mix(n01, n11, u), v);
    }
};
} // namespace

Texture make_marble_texture(uint32_t size, float scale, vec3 a, vec3 b, uint32_t seed) {
    constexpr int base_period = 8; // lattice cells across the texture at the first octave
    const GradientNoise noise(seed);
    std::vector<vec3> texels(size_t(size) * size);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const float s = float(x) / float(size), tt = float(y) / float(size);
            float turbulence = 0.0f, amplitude = 1.0f;
            int frequency = 1;
            for (int octave = 0; octave < 6; ++octave) {
                // Each octave doubles the lattice frequency and its wrap period with it, so the
                // sum stays tileable.
                const int cells = base_period * frequency;
                turbulence +=
                    amplitude * std::abs(noise(s * float(cells), tt * float(cells), cells));
                amplitude *= 0.5f;
                frequency *= 2;
            }
            // The vein phase advances an integer number of periods across the tile.
            const float phase = TWO_PI * std::round(scale) * s + 6.0f * turbulence;
            const float vein = 0.5f + 0.5f * std::sin(phase);
            texels[size_t(y) * size + x] = glm::mix(a, b, std::pow(vein, 0.5f));
        }
    return texture_from_linear_rgb(size, size, texels);
}

} // namespace tp
