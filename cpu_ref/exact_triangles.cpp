#include "cpu_ref/exact_triangles.h"

#include "cpu_ref/isa_clones.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tp {

namespace {

constexpr double kMaxMitre = 1024.0; // corner growth in units of delta

// Embree's barycentrics (u, v) of the grown triangle and its unnormalized normal give each
// candidate's distance from the grown edges: lambda_i |Ng| = distance_i |edge_i|. If lambda_i
// |Ng| exceeds 2 delta times the mesh's longest grown edge for every i, the candidate is more than
// 2 delta inside every grown edge, so more than delta inside the exact triangle: far beyond
// Embree's rounding (delta / 6) and intersect_triangle's, which would accept it too.
// In double: |Ng|^2 is quartic in the coordinates and overflows float from edges of 2^32 on.
bool margin_accepts(const ExactMesh& mesh, float u, float v, vec3 ng) {
    const double lambda = double(glm::min(glm::min(u, v), 1.0f - u - v));
    const double margin = double(mesh.margin);
    return lambda > 0.0 &&
           lambda * lambda * glm::dot(glm::dvec3(ng), glm::dvec3(ng)) > margin * margin;
}

// The candidate i of a filter call: accepted by margin or by the exact test. Records it in the
// query for an intersection (record = true).
bool keep_candidate(const RTCFilterFunctionNArguments* args, unsigned i, bool record) {
    const auto& mesh = *static_cast<const ExactMesh*>(args->geometryUserPtr);
    RTCRayN* ray = args->ray;
    RTCHitN* hit = args->hit;
    const unsigned n = args->N;
    const vec3 org(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i));
    const vec3 dir(RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i));
    const vec3 ng(RTCHitN_Ng_x(hit, n, i), RTCHitN_Ng_y(hit, n, i), RTCHitN_Ng_z(hit, n, i));
    auto* query = const_cast<ExactQuery*>(reinterpret_cast<const ExactQuery*>(args->context));
    bool tested = false;
    vec3 tuv(0.0f);
    if (!margin_accepts(mesh, RTCHitN_u(hit, n, i), RTCHitN_v(hit, n, i), ng)) {
        const uvec3 t = mesh.triangles[RTCHitN_primID(hit, n, i)];
        if (!intersect_triangle(org, watertight_ray(dir), mesh.vertices[t.x], mesh.vertices[t.y],
                                mesh.vertices[t.z], std::numeric_limits<float>::infinity(), tuv))
            return false;
        tested = true;
    }
    if (query->coverage) {
        const uint32_t prim = RTCHitN_primID(hit, n, i);
        const unsigned inst = RTCHitN_instID(hit, n, i, 0);
        // A flattened mesh's triangles carry their instance index as geometry ID (embree_accel).
        const uint32_t instance =
            inst != RTC_INVALID_GEOMETRY_ID ? inst : RTCHitN_geomID(hit, n, i);
        const vec3 h = tested ? tuv : exact_margin_hit(mesh, prim, org, dir);
        if (!query->coverage->covers(query->coverage->engine, instance, prim, vec2(h.y, h.z),
                                     query->coverage->ray))
            return false;
    }
    if (record) query->records[i] = ExactRecord{&mesh, org, dir, tested, tuv};
    return true;
}

void filter(const RTCFilterFunctionNArguments* args, bool record) {
    for (unsigned i = 0; i < args->N; ++i)
        if (args->valid[i] != 0 && !keep_candidate(args, i, record)) args->valid[i] = 0;
}

} // namespace

double exact_delta(double extent) {
    return std::ldexp(extent, -17);
}

double mesh_extent(const ExactMesh& mesh, double camera_extent) {
    double m = camera_extent;
    for (const vec3& p : mesh.vertices)
        m = std::max(m, double(glm::max(std::abs(p.x), glm::max(std::abs(p.y), std::abs(p.z)))));
    return m;
}

float grow_triangles(const ExactMesh& mesh, double delta, vec3* out) {
    double longest = 0.0;
    for (size_t k = 0; k < mesh.triangles.size(); ++k) {
        const uvec3 t = mesh.triangles[k];
        const glm::dvec3 p[3] = {glm::dvec3(mesh.vertices[t.x]), glm::dvec3(mesh.vertices[t.y]),
                                 glm::dvec3(mesh.vertices[t.z])};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        vec3* q = out + 3 * k;
        if (!(glm::dot(n, n) > 0.0)) {
            for (int i = 0; i < 3; ++i) q[i] = vec3(p[i]);
            continue;
        }
        // Outward in-plane normal of edge e (p[e] -> p[e + 1]): the interior of a
        // counter-clockwise triangle lies to the left of each edge, seen from n.
        glm::dvec3 out_normal[3];
        for (int e = 0; e < 3; ++e)
            out_normal[e] = glm::normalize(glm::cross(p[(e + 1) % 3] - p[e], n));
        for (int i = 0; i < 3; ++i) {
            // The corner where the two moved edges meet: along the bisector, at delta /
            // sin(theta / 2) = delta |a + b| / (1 + a . b) for the unit normals a, b.
            const glm::dvec3 a = out_normal[(i + 2) % 3], b = out_normal[i];
            glm::dvec3 mitre = (a + b) / (1.0 + glm::dot(a, b));
            if (!(glm::length(mitre) <= kMaxMitre)) mitre = glm::normalize(a + b) * kMaxMitre;
            q[i] = vec3(p[i] + delta * mitre);
        }
        for (int i = 0; i < 3; ++i)
            longest = std::max(longest, double(glm::length(q[(i + 1) % 3] - q[i])));
    }
    return float(2.0 * delta * longest);
}

TP_ISA_CLONES void exact_intersect_filter(const RTCFilterFunctionNArguments* args) {
    filter(args, true);
}

TP_ISA_CLONES void exact_occluded_filter(const RTCFilterFunctionNArguments* args) {
    filter(args, false);
}

TP_ISA_CLONES vec3 exact_hit(const ExactRecord& record, uint32_t primitive) {
    if (record.tested) return record.tuv;
    return exact_margin_hit(*record.mesh, primitive, record.org, record.dir);
}

vec3 exact_margin_hit(const ExactMesh& mesh, uint32_t primitive, vec3 org, vec3 dir) {
    // A hit the margin accepted lies more than delta inside the triangle, so no edge decision is
    // left: the distance from the plane as intersect_triangle takes it (the same expression) and
    // the barycentrics of Moeller & Trumbore (1997), equal to the watertight test's to
    // rounding. Two independent divisions instead of intersect_triangle's chain of the
    // ray's shear and its own: this runs once per hit (docs/stress.md, "Embree at vertices").
    const uvec3 t = mesh.triangles[primitive];
    const std::vector<vec3>& v = mesh.vertices;
    const vec3 e1 = v[t.y] - v[t.x], e2 = v[t.z] - v[t.x];
    const vec3 a = v[t.x] - org;
    const vec3 n = triangle_plane_normal(v[t.x], v[t.y], v[t.z]);
    const float distance = dot(a, n) / dot(dir, n);
    const vec3 p = cross(dir, e2), q = cross(-a, e1);
    const float inv_det = 1.0f / dot(e1, p);
    return vec3(distance, dot(-a, p) * inv_det, dot(dir, q) * inv_det);
}

} // namespace tp
