#include "scene/tangents.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace tp {
namespace {

// v made orthogonal to the unit vector n (n may be zero: v unchanged) and normalized; zero if
// nothing is left.
glm::dvec3 orthonormalized(const glm::dvec3& v, const glm::dvec3& n) {
    const glm::dvec3 o = v - n * glm::dot(n, v);
    const double len = glm::length(o);
    return len > 0.0 && std::isfinite(len) ? o / len : glm::dvec3(0.0);
}

glm::dvec3 unit_or_zero(const glm::dvec3& v) {
    const double len = glm::length(v);
    return len > 0.0 && std::isfinite(len) ? v / len : glm::dvec3(0.0);
}

// The angle between the edges a and b at a corner.
double corner_angle(const glm::dvec3& a, const glm::dvec3& b) {
    const double c = glm::dot(unit_or_zero(a), unit_or_zero(b));
    return std::acos(std::clamp(c, -1.0, 1.0));
}

// A unit vector orthogonal to the unit vector n (Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 2017), or +X for a zero n.
glm::dvec3 any_tangent(const glm::dvec3& n) {
    if (n == glm::dvec3(0.0)) return {1.0, 0.0, 0.0};
    const double s = std::copysign(1.0, n.z);
    const double a = -1.0 / (s + n.z);
    return {1.0 + s * n.x * n.x * a, s * n.x * n.y * a, -s * n.x};
}

} // namespace

std::vector<vec4> generate_tangents(const Mesh& mesh, const TextureSlot& slot) {
    const size_t nv = mesh.positions.size();
    const std::vector<vec2>& uvs = (slot.sampling & SLOT_UV1) != 0u ? mesh.uvs1 : mesh.uvs;
    std::vector<glm::dvec3> normal(nv, glm::dvec3(0.0)), tangent(nv, glm::dvec3(0.0)),
        up(nv, glm::dvec3(0.0));
    for (size_t v = 0; v < mesh.normals.size(); ++v) normal[v] = unit_or_zero(mesh.normals[v]);
    if (uvs.size() == nv)
        for (const uvec3& tri : mesh.triangles) {
            glm::dvec3 p[3];
            glm::dvec2 st[3];
            for (int k = 0; k < 3; ++k) {
                p[k] = mesh.positions[tri[k]];
                const glm::dvec3 uv(glm::dvec2(uvs[tri[k]]), 1.0);
                st[k] = {glm::dot(glm::dvec3(slot.transform_s), uv),
                         glm::dot(glm::dvec3(slot.transform_t), uv)};
            }
            const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
            const glm::dvec2 d1 = st[1] - st[0], d2 = st[2] - st[0];
            const double r = d1.x * d2.y - d2.x * d1.y;
            if (!(r != 0.0) || !std::isfinite(r)) continue; // no area in (s, t): no direction
            // Lengyel: dP/ds = (e1 dt2 - e2 dt1) / r, dP/dt = (e2 ds1 - e1 ds2) / r; only the
            // directions are used, so the division is by r's sign.
            const double sign = r > 0.0 ? 1.0 : -1.0;
            const glm::dvec3 t = (e1 * d2.y - e2 * d1.y) * sign;
            const glm::dvec3 u = -(e2 * d1.x - e1 * d2.x) * sign;
            for (int k = 0; k < 3; ++k) {
                const uint32_t v = tri[k];
                const double angle = corner_angle(p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k]);
                tangent[v] += angle * orthonormalized(t, normal[v]);
                up[v] += angle * orthonormalized(u, normal[v]);
            }
        }
    std::vector<vec4> out(nv);
    for (size_t v = 0; v < nv; ++v) {
        glm::dvec3 t = orthonormalized(tangent[v], normal[v]);
        if (t == glm::dvec3(0.0)) t = any_tangent(normal[v]);
        const double w = glm::dot(glm::cross(normal[v], t), up[v]) < 0.0 ? -1.0 : 1.0;
        out[v] = vec4(vec3(t), float(w));
    }
    return out;
}

void unweld_flat_normals(Mesh& mesh) {
    Mesh out;
    out.name = mesh.name;
    for (const uvec3& tri : mesh.triangles) {
        const glm::dvec3 a = mesh.positions[tri.x], b = mesh.positions[tri.y],
                         c = mesh.positions[tri.z];
        const vec3 n = vec3(glm::normalize(glm::cross(b - a, c - a)));
        const uint32_t first = uint32_t(out.positions.size());
        for (int k = 0; k < 3; ++k) {
            out.positions.push_back(mesh.positions[tri[k]]);
            out.normals.push_back(n);
            if (!mesh.uvs.empty()) out.uvs.push_back(mesh.uvs[tri[k]]);
            if (!mesh.uvs1.empty()) out.uvs1.push_back(mesh.uvs1[tri[k]]);
        }
        out.triangles.push_back({first, first + 1, first + 2});
    }
    mesh = std::move(out);
}

void add_tangent_frame(Mesh& mesh, const TextureSlot& slot) {
    if (mesh.normals.empty()) unweld_flat_normals(mesh);
    if (mesh.tangents.empty()) mesh.tangents = generate_tangents(mesh, slot);
}

} // namespace tp
