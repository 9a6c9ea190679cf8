// Per-ray traversal work of compute mode's two BVH layouts, counted on the host (issue 25,
// "Measured why"): the rays are the CPU reference's own paths (CpuIntegrator::record, the same
// path loop and random numbers as the GPU), traced again through the BvhBuild that the GPU
// renderer uploads, by C++ ports of the two shader loops (shaders/trace_bvh.glsl,
// shaders/trace_cwbvh.glsl) that count instead of shading, one level and two. Counts per ray
// do not depend on the device; the shaders stay free of counters. Shadow rays: see main().
//
// usage: work_counts SCENE WIDTH HEIGHT SPP [--eye x,y,z --target x,y,z --fov f]
// prints one JSON object per (layout, ray kind).
#include "cpu_ref/embree_accel.h"
#include "cpu_ref/integrator.h"
#include "scene/features.h"
#include "scene/flatten.h"
#include "scene/load.h"
#include "shared/intersect.h"
#include "shared/surface.h"
#include "vulkan_rt/accel/bvh_builder.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace tp;

namespace {

struct Work {
    uint64_t rays = 0, nodes = 0, box_tests = 0, box_slots = 0, box_hits = 0, triangles = 0,
             pushes = 0, pops = 0, hits = 0, mismatches = 0, instances = 0;
    void add(const Work& w) {
        rays += w.rays, nodes += w.nodes, box_tests += w.box_tests, box_slots += w.box_slots,
            box_hits += w.box_hits, triangles += w.triangles, pushes += w.pushes, pops += w.pops,
            hits += w.hits, mismatches += w.mismatches, instances += w.instances;
    }
};

struct Query {
    vec3 org, dir;
    float tmax;
    bool any_hit;
    bool expect; // what the CPU reference's path found (hit / occluded)
};

bool tri_test(const BvhTriangle& t, vec3 org, const WatertightRay& wr, float& tmax) {
    vec3 tuv;
    if (!intersect_triangle_normal(org, wr, t.v0, t.v1, t.v2, t.normal, tmax, tuv)) return false;
    tmax = tuv.x;
    return true;
}

// trace_bvh.glsl: box_tests = non-empty children tested (2 per node when full).
bool binary_trace(const BvhBuild& b, const FlatScene& scene, const Query& q, Work& w) {
    const uint32_t FLAG = 0x80000000u;
    const bool two_level = !b.one_level;
    const vec3 world_inv = ray_inverse_direction(q.dir);
    vec3 org = q.org, inv = world_inv;
    WatertightRay wr = watertight_ray(q.dir);
    uint32_t inst = BVH_EMPTY, inst_sp = 0;
    float tmax = q.tmax;
    bool found = false;
    uint32_t stack[BVH_STACK_SIZE];
    uint32_t sp = 0, next = b.top_root;
    for (;;) {
        if (next == BVH_EMPTY) {
            if (two_level && inst != BVH_EMPTY && sp == inst_sp) {
                inst = BVH_EMPTY;
                org = q.org;
                inv = world_inv;
            }
            if (sp == 0) break;
            next = stack[--sp];
            ++w.pops;
        }
        uint32_t entry = next;
        next = BVH_EMPTY;
        if (two_level && (entry & FLAG)) {
            inst = entry & ~FLAG;
            inst_sp = sp;
            const Instance& I = scene.instances[inst];
            org = instance_point_to_object(I, q.org);
            const vec3 dir = instance_vector_to_object(I, q.dir);
            inv = ray_inverse_direction(dir);
            wr = watertight_ray(dir);
            entry = b.mesh_roots[I.mesh];
            ++w.instances;
        }
        const BvhNode& n = b.nodes[entry];
        ++w.nodes;
        float t0 = 0, t1 = 0;
        w.box_tests += (n.ref0 != BVH_EMPTY) + (n.ref1 != BVH_EMPTY);
        w.box_slots += 2;
        bool h0 = n.ref0 != BVH_EMPTY && intersect_aabb(org, inv, n.lo0, n.hi0, tmax, t0);
        bool h1 = n.ref1 != BVH_EMPTY && intersect_aabb(org, inv, n.lo1, n.hi1, tmax, t1);
        w.box_hits += h0 + h1;
        if (!two_level || inst != BVH_EMPTY) {
            for (int c = 0; c < 2; ++c) {
                bool leaf = c == 0 ? h0 && n.count0 > 0 : h1 && n.count1 > 0;
                if (!leaf) continue;
                uint32_t first = c == 0 ? n.ref0 : n.ref1;
                uint32_t end = first + (c == 0 ? n.count0 : n.count1);
                for (uint32_t i = first; i < end; ++i) {
                    ++w.triangles;
                    if (!tri_test(b.triangles[i], org, wr, tmax)) continue;
                    found = true;
                    if (q.any_hit) return true;
                }
            }
            h0 = h0 && n.count0 == 0;
            h1 = h1 && n.count1 == 0;
        }
        const uint32_t e0 = n.count0 > 0 ? (FLAG | n.ref0) : n.ref0;
        const uint32_t e1 = n.count1 > 0 ? (FLAG | n.ref1) : n.ref1;
        if (h0 && h1) {
            stack[sp++] = t0 <= t1 ? e1 : e0;
            ++w.pushes;
            next = t0 <= t1 ? e0 : e1;
        } else if (h0) {
            next = e0;
        } else if (h1) {
            next = e1;
        }
    }
    return found;
}

uint32_t octant_of(vec3 inv) {
    return (inv.x < 0 ? 0u : 4u) | (inv.y < 0 ? 0u : 2u) | (inv.z < 0 ? 0u : 1u);
}

// cwbvh_child_hits of trace_cwbvh.glsl: the same float expressions per slot.
uint32_t wide_hits(const WideBvhNode& n, vec3 org, vec3 inv, uint32_t oct, float tmax, Work& w) {
    vec3 scale, p(n.p[0], n.p[1], n.p[2]);
    for (int k = 0; k < 3; ++k) {
        uint32_t bits = uint32_t(n.e[k]) << 23;
        std::memcpy(&scale[k], &bits, 4);
    }
    vec3 a = scale * inv, b = (p - org) * inv;
    vec3 pad = (abs(b) + 256.0f * abs(a)) * (1.0f / 1048576.0f);
    vec3 b_in = b - pad, b_out = b + pad;
    uint32_t hits = 0;
    w.box_slots += 8;
    for (int s = 0; s < 8; ++s) {
        uint32_t m = n.meta[s];
        if (m == 0) continue;
        ++w.box_tests;
        float tin = 0.0f, tout = FLOAT_MAX;
        for (int k = 0; k < 3; ++k) {
            bool pos = inv[k] >= 0.0f;
            float qi = pos ? n.qlo[k][s] : n.qhi[k][s], qo = pos ? n.qhi[k][s] : n.qlo[k][s];
            tin = std::max(tin, qi * a[k] + b_in[k]);
            tout = std::min(tout, qo * a[k] + b_out[k]);
        }
        tout *= AABB_FAR_SCALE;
        if (!(tin <= tout && tin < tmax)) continue;
        ++w.box_hits;
        bool inner = (m & 0x18u) == 0x18u;
        uint32_t bit = inner ? ((m & 0x1fu) ^ oct) : (m & 0x1fu);
        hits |= (m >> 5u) << bit;
    }
    return hits;
}

// trace_cwbvh.glsl.
bool wide_trace(const BvhBuild& b, const FlatScene& scene, const Query& q, Work& w) {
    const uint32_t NODE_BITS = 0xff000000u;
    const bool two_level = !b.one_level;
    const vec3 world_inv = ray_inverse_direction(q.dir);
    const uint32_t world_oct = octant_of(world_inv);
    vec3 org = q.org, inv = world_inv;
    uint32_t oct = world_oct;
    WatertightRay wr = watertight_ray(q.dir);
    uint32_t inst = BVH_EMPTY, inst_sp = 0;
    float tmax = q.tmax;
    bool found = false;
    uint32_t stack_x[CWBVH_STACK_SIZE], stack_y[CWBVH_STACK_SIZE];
    uint32_t sp = 0, gx = b.top_root, gy = 0x80000000u;
    auto push = [&](uint32_t x, uint32_t y) {
        stack_x[sp] = x, stack_y[sp++] = y;
        ++w.pushes;
    };
    for (;;) {
        uint32_t tx = 0, ty = 0;
        if (gy & NODE_BITS) {
            const uint32_t bit = 31 - std::countl_zero(gy);
            gy &= ~(1u << bit);
            const uint32_t slot = (bit - 24u) ^ oct;
            const uint32_t node = gx + std::popcount(gy & ((1u << slot) - 1u) & 0xffu);
            if (gy & NODE_BITS) push(gx, gy);
            const WideBvhNode& n = b.wide_nodes[node];
            ++w.nodes;
            const uint32_t hits = wide_hits(n, org, inv, oct, tmax, w);
            gx = n.child_base;
            gy = (hits & NODE_BITS) | n.imask;
            tx = n.triangle_base;
            ty = hits & ~NODE_BITS;
        } else {
            tx = gx, ty = gy;
            gx = gy = 0;
        }
        while (ty) {
            const uint32_t bit = 31 - std::countl_zero(ty);
            ty &= ~(1u << bit);
            const uint32_t i = tx + bit;
            if (two_level && inst == BVH_EMPTY) {
                if (ty) push(tx, ty);
                if (gy & NODE_BITS) push(gx, gy);
                inst = b.triangles[i].instance;
                inst_sp = sp;
                const Instance& I = scene.instances[inst];
                org = instance_point_to_object(I, q.org);
                const vec3 dir = instance_vector_to_object(I, q.dir);
                inv = ray_inverse_direction(dir);
                oct = octant_of(inv);
                wr = watertight_ray(dir);
                gx = b.mesh_roots[I.mesh], gy = 0x80000000u;
                ++w.instances;
                break;
            }
            ++w.triangles;
            if (!tri_test(b.triangles[i], org, wr, tmax)) continue;
            found = true;
            if (q.any_hit) return true;
        }
        if (!(gy & NODE_BITS)) {
            if (two_level && inst != BVH_EMPTY && sp == inst_sp) {
                inst = BVH_EMPTY;
                org = q.org;
                inv = world_inv;
                oct = world_oct;
            }
            if (sp == 0) break;
            --sp, gx = stack_x[sp], gy = stack_y[sp], ++w.pops;
        }
    }
    return found;
}

vec3 parse3(const char* s) {
    vec3 v;
    std::sscanf(s, "%f,%f,%f", &v.x, &v.y, &v.z);
    return v;
}

void print(const char* scene, const char* layout, const char* kind, const Work& w, double node_b,
           const BvhBuild& b) {
    double r = double(std::max<uint64_t>(w.rays, 1));
    std::printf("{\"scene\": \"%s\", \"layout\": \"%s\", \"rays\": \"%s\", \"count\": %llu, "
                "\"nodes\": %.3f, \"box_tests\": %.3f, \"box_slots\": %.3f, \"box_hits\": %.3f, "
                "\"triangles\": %.3f, \"pushes\": %.3f, \"pops\": %.3f, \"hit_fraction\": %.4f, "
                "\"mismatch_fraction\": %.5f, "
                "\"node_bytes\": %.0f, \"bytes_per_ray\": %.1f, \"bvh_bytes\": %llu, "
                "\"instance_entries\": %.3f}\n",
                scene, layout, kind, (unsigned long long)w.rays, w.nodes / r, w.box_tests / r,
                w.box_slots / r, w.box_hits / r, w.triangles / r, w.pushes / r, w.pops / r,
                w.hits / r, w.mismatches / r, node_b, (w.nodes * node_b + w.triangles * 64.0) / r,
                (unsigned long long)b.bytes(), w.instances / r);
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 5) {
        std::fprintf(stderr, "usage: work_counts SCENE WIDTH HEIGHT SPP [--eye --target --fov]\n");
        return 2;
    }
    std::vector<std::string> warnings;
    Scene scene = load_scene(argv[1], warnings);
    SceneOverrides o;
    o.width = uint32_t(std::stoul(argv[2]));
    o.height = uint32_t(std::stoul(argv[3]));
    o.spp = uint32_t(std::stoul(argv[4]));
    for (int i = 5; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--eye")) o.eye = parse3(argv[i + 1]);
        if (!std::strcmp(argv[i], "--target")) o.target = parse3(argv[i + 1]);
        if (!std::strcmp(argv[i], "--fov")) o.fov = std::stof(argv[i + 1]);
    }
    apply_overrides(scene, o);
    FlatScene flat = flatten(scene);
    flat.params.seed = 1;
    const uint32_t features = render_feature_mask(flat, false);
    EmbreeAccel accel(flat);
    CpuIntegrator integrator(flat, accel, FEATURES_ALL, flat.params.seed);
    // The queries of every path: each vertex's incoming ray (camera: bounce 0, else extension),
    // each traced shadow ray. The log has no light distance, so a shadow ray's tmax is its
    // distance to the first surface along light_wi when the path found it unoccluded (the
    // light, or past it for distant lights), else unbounded (an any-hit query stops at the
    // first occluder either way); its origin is the vertex moved off the surface as spawn_ray.
    std::vector<Query> queries[3];
    std::vector<PathVertex> log;
    RayCounts rc;
    const Camera& cam = flat.params.camera;
    for (uint32_t y = 0; y < cam.height; ++y)
        for (uint32_t x = 0; x < cam.width; ++x)
            for (uint32_t s = 0; s < flat.spp; ++s) {
                log.clear();
                integrator.record(x, y, s, rc, log);
                for (const PathVertex& v : log) {
                    queries[v.bounce == 0 ? 0 : 1].push_back(
                        {v.ray_origin, v.ray_dir, FLOAT_MAX, false, v.event == VERTEX_HIT});
                    if (v.shadow == SHADOW_NOT_TRACED) continue;
                    vec3 n = dot(v.light_wi, v.ng) > 0 ? v.ng : -v.ng;
                    vec3 org = v.position +
                               n * (1e-4f * std::max(1.0f, std::max({std::abs(v.position.x),
                                                                     std::abs(v.position.y),
                                                                     std::abs(v.position.z)})));
                    Ray r;
                    r.origin = org;
                    r.dir = v.light_wi;
                    r.tmax = FLOAT_MAX;
                    r.pad0 = 0u;
                    float tmax = FLOAT_MAX;
                    if (v.shadow == SHADOW_UNOCCLUDED) {
                        const Hit h = accel.intersect(r);
                        if (h.found) tmax = h.t * (1.0f - 1e-4f);
                    }
                    queries[2].push_back(
                        {org, v.light_wi, tmax, true, v.shadow == SHADOW_OCCLUDED});
                }
            }
    const char* kinds[3] = {"camera", "extension", "shadow"};
    BvhBuild bb = build_bvh(flat, features, BvhLayout::binary);
    BvhBuild bw = build_bvh(flat, features, BvhLayout::wide);
    Work all_b, all_w;
    for (int k = 0; k < 3; ++k) {
        Work wb, ww;
        for (const Query& q : queries[k]) {
            ++wb.rays, ++ww.rays;
            const bool hb = binary_trace(bb, flat, q, wb), hw = wide_trace(bw, flat, q, ww);
            wb.hits += hb, ww.hits += hw;
            wb.mismatches += hb != q.expect, ww.mismatches += hw != q.expect;
        }
        print(argv[1], "binary", kinds[k], wb, 64.0, bb);
        print(argv[1], "wide", kinds[k], ww, 80.0, bw);
        all_b.add(wb), all_w.add(ww);
    }
    print(argv[1], "binary", "all", all_b, 64.0, bb);
    print(argv[1], "wide", "all", all_w, 80.0, bw);
    return 0;
}
