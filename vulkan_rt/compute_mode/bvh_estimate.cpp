#include "vulkan_rt/compute_mode/bvh_estimate.h"

#include "vulkan_rt/compute_mode/bvh_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <bitset>
#include <limits>
#include <map>

namespace tp {
namespace {

struct Box {
    glm::dvec3 lo{std::numeric_limits<double>::max()}, hi{-std::numeric_limits<double>::max()};
    void add(const Box& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    double area() const {
        const glm::dvec3 d = glm::max(hi - lo, glm::dvec3(0.0));
        return d.x * d.y + d.y * d.z + d.z * d.x;
    }
};

void add_scaled(BvhEstimate& e, const BvhEstimate& o, double p) {
    e.nodes += p * o.nodes;
    e.boxes += p * o.boxes;
    e.triangles += p * o.triangles;
    e.instances += p * o.instances;
}

class Estimator {
  public:
    Estimator(const BvhBuild& bvh, const FlatScene& scene)
        : bvh_(bvh), scene_(scene), wide_(bvh.layout == BvhLayout::wide) {}

    BvhEstimate run() { return tree(bvh_.top_root, !bvh_.one_level); }

  private:
    // The work of a tree per ray that meets its root's box; `top`: its leaves are instances.
    BvhEstimate tree(uint32_t root, bool top) {
        BvhEstimate e;
        Box all;
        for (const Child& c : children(root)) all.add(c.box);
        const double area = all.area();
        visit(root, area, 1.0, top, e);
        return e;
    }

    struct Child {
        Box box;
        bool inner;
        uint32_t ref;   // inner: node index; leaf: first item (binary top level: the instance)
        uint32_t count; // leaf items
    };

    std::vector<Child> children(uint32_t node) const {
        std::vector<Child> out;
        if (!wide_) {
            const BvhNode& n = bvh_.nodes[node];
            auto add = [&](vec3 lo, vec3 hi, uint32_t ref, uint32_t count) {
                if (count == 0 && ref == BVH_EMPTY) return;
                out.push_back({{glm::dvec3(lo), glm::dvec3(hi)}, count == 0, ref, count});
            };
            add(n.lo0, n.hi0, n.ref0, n.count0);
            add(n.lo1, n.hi1, n.ref1, n.count1);
            return out;
        }
        const WideBvhNode& n = bvh_.wide_nodes[node];
        for (uint32_t s = 0; s < 8; ++s) {
            if (n.meta[s] == 0) continue;
            Child c;
            wide_child_box(n, s, c.box.lo, c.box.hi);
            c.inner = (n.imask >> s) & 1u;
            if (c.inner) {
                c.ref = n.child_base + uint32_t(std::bitset<8>(n.imask & ((1u << s) - 1u)).count());
                c.count = 0;
            } else {
                c.ref = n.triangle_base + (n.meta[s] & 0x1fu);
                c.count = uint32_t(std::bitset<3>(n.meta[s] >> 5).count());
            }
            out.push_back(c);
        }
        return out;
    }

    // Node `node`, met with probability p by a ray through the root's box of area root_area.
    void visit(uint32_t node, double root_area, double p, bool top, BvhEstimate& e) {
        e.nodes += p;
        e.boxes += p * (wide_ ? 8.0 : 2.0);
        for (const Child& c : children(node)) {
            // A ray that meets a root without area (a point, a segment) meets all of it.
            const double q = root_area > 0.0 ? c.box.area() / root_area : 1.0;
            if (c.inner) {
                visit(c.ref, root_area, q, top, e);
            } else if (!top) {
                e.triangles += q * c.count;
            } else {
                const uint32_t instance = wide_ ? bvh_.wide_triangles.instance_item(c.ref) : c.ref;
                e.instances += q;
                add_scaled(e, mesh(scene_.instances[instance].mesh), q);
            }
        }
    }

    const BvhEstimate& mesh(uint32_t m) {
        auto it = meshes_.find(m);
        if (it == meshes_.end()) it = meshes_.emplace(m, tree(bvh_.mesh_roots[m], false)).first;
        return it->second;
    }

    const BvhBuild& bvh_;
    const FlatScene& scene_;
    bool wide_;
    std::map<uint32_t, BvhEstimate> meshes_;
};

} // namespace

BvhEstimate estimate_bvh_work(const BvhBuild& bvh, const FlatScene& scene) {
    return Estimator(bvh, scene).run();
}

bool auto_prefers_wide(const BvhEstimate& binary) {
    return binary.nodes >= kAutoWideMinBinaryNodes;
}

std::string describe(const BvhEstimate& e) {
    return fmt::format("nodes {:.3f} boxes {:.3f} triangles {:.3f} instances {:.3f}", e.nodes,
                       e.boxes, e.triangles, e.instances);
}

} // namespace tp
