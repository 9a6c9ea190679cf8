#include "scene/dielectric_interfaces.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <fmt/format.h>
#include <glm/mat4x4.hpp>
#include <map>
#include <tuple>

namespace tp {

namespace {

struct TriangleRef {
    uint32_t object, triangle;
};

// A triangle's world-space corners as bits, rotated to start at the lexicographically smallest
// corner: the two windings of one vertex set get two keys. The reversed winding (a, c, b) of a
// key (a, b, c) starts at the same smallest corner, so its key is the same with b and c swapped.
using Key = std::array<uint64_t, 9>;

Key reversed(Key k) {
    std::swap_ranges(k.begin() + 3, k.begin() + 6, k.begin() + 6);
    return k;
}

struct Keyed {
    Key key;
    TriangleRef ref;
    bool operator<(const Keyed& o) const {
        return std::tie(key, ref.object, ref.triangle) <
               std::tie(o.key, o.ref.object, o.ref.triangle);
    }
};

bool before(const glm::dvec3& a, const glm::dvec3& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
}

Key key_of(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const std::array<glm::dvec3, 3> v{a, b, c};
    const int first =
        before(v[1], v[0]) ? (before(v[2], v[1]) ? 2 : 1) : (before(v[2], v[0]) ? 2 : 0);
    Key k;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3 p = v[(first + i) % 3] + glm::dvec3(0.0); // -0 + 0 = +0: one key per point
        std::memcpy(&k[3 * i], &p, sizeof(glm::dvec3));
    }
    return k;
}

// M p + T in double, as the scene keeps positions (scene/scene.h): equal for both objects
// exactly where the two meshes were built to share the vertex (translated, scaled or rotated
// copies with exact products).
glm::dvec3 world_point(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

bool merges(const Material& m) {
    return m.type == MATERIAL_DIELECTRIC && m.ke == vec3(0.0f);
}

// The triangles of `m` that `take` selects, with only the vertices they use.
Mesh sub_mesh(const Mesh& m, const std::vector<bool>& take, std::string name) {
    Mesh out;
    out.name = std::move(name);
    std::vector<uint32_t> slot(m.positions.size(), NO_INDEX);
    const auto vertex = [&](uint32_t v) {
        if (slot[v] == NO_INDEX) {
            slot[v] = uint32_t(out.positions.size());
            out.positions.push_back(m.positions[v]);
            if (!m.normals.empty()) out.normals.push_back(m.normals[v]);
            if (!m.uvs.empty()) out.uvs.push_back(m.uvs[v]);
        }
        return slot[v];
    };
    for (size_t t = 0; t < m.triangles.size(); ++t)
        if (take[t]) {
            const uvec3 tri = m.triangles[t];
            out.triangles.push_back(uvec3(vertex(tri.x), vertex(tri.y), vertex(tri.z)));
        }
    return out;
}

} // namespace

std::optional<DielectricInterfaces> merge_dielectric_interfaces(const Scene& scene) {
    std::vector<uint32_t> candidates;
    for (uint32_t o = 0; o < scene.objects.size(); ++o)
        if (merges(scene.materials[scene.objects[o].material])) candidates.push_back(o);
    if (candidates.size() < 2) return std::nullopt;

    // Sorted by key (80 bytes a triangle): each triangle's reversed partners are one range.
    std::vector<Keyed> by_key;
    for (uint32_t o : candidates) {
        const Object& obj = scene.objects[o];
        const Mesh& m = scene.meshes[obj.mesh];
        const glm::dmat4& to_world = obj.transform;
        for (uint32_t t = 0; t < m.triangles.size(); ++t) {
            const uvec3 tri = m.triangles[t];
            by_key.push_back({key_of(world_point(to_world, m.positions[tri.x]),
                                     world_point(to_world, m.positions[tri.y]),
                                     world_point(to_world, m.positions[tri.z])),
                              {o, t}});
        }
    }
    // Each triangle's own key, in the order the pairing below visits them.
    std::vector<Key> keys(by_key.size());
    for (size_t k = 0; k < by_key.size(); ++k) keys[k] = by_key[k].key;
    std::sort(by_key.begin(), by_key.end());

    // removed[o][t]: triangle t leaves object o (to an interface, or dropped as the copy).
    std::vector<std::vector<bool>> removed(scene.objects.size());
    for (uint32_t o : candidates)
        removed[o].assign(scene.meshes[scene.objects[o].mesh].triangles.size(), false);
    // (A, B) -> the triangles of A that become the interface between A and B (A < B).
    std::map<std::pair<uint32_t, uint32_t>, std::vector<bool>> interfaces;
    uint64_t faces = 0;
    size_t visit = 0;
    for (uint32_t o : candidates)
        for (uint32_t t = 0; t < removed[o].size(); ++t) {
            const Keyed partner{reversed(keys[visit++]), {0, 0}};
            if (removed[o][t]) continue;
            for (auto it = std::lower_bound(by_key.begin(), by_key.end(), partner);
                 it != by_key.end() && it->key == partner.key; ++it) {
                const TriangleRef r = it->ref;
                if (r.object == o || removed[r.object][r.triangle]) continue;
                const TriangleRef a = r.object < o ? r : TriangleRef{o, t};
                const TriangleRef b = r.object < o ? TriangleRef{o, t} : r;
                std::vector<bool>& mine = interfaces[{a.object, b.object}];
                mine.resize(removed[a.object].size(), false);
                mine[a.triangle] = true;
                removed[a.object][a.triangle] = removed[b.object][b.triangle] = true;
                ++faces;
                break;
            }
        }
    if (faces == 0) return std::nullopt;

    DielectricInterfaces out;
    out.faces = faces;
    Scene& s = out.scene;
    s = scene;
    // One material per ordered pair of materials: the medium of A (inside, against the normal)
    // over the medium of B; a ray crossing it is filtered by both objects' tints, as it was by
    // the two surfaces it replaces.
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> interface_material;
    for (size_t k = s.material_names.size(); k < s.materials.size(); ++k)
        s.material_names.push_back(fmt::format("material {}", k));
    for (const auto& [pair, take] : interfaces) {
        const Object a = s.objects[pair.first], b = s.objects[pair.second];
        const auto key = std::make_pair(a.material, b.material);
        if (!interface_material.count(key)) {
            Material m = s.materials[a.material];
            const Material& mb = s.materials[b.material];
            m.ior = m.ior / mb.ior;
            m.tf = m.tf * mb.tf;
            interface_material[key] = uint32_t(s.materials.size());
            s.materials.push_back(m);
            s.material_names.push_back(
                fmt::format("{}|{}", s.material_names[a.material], s.material_names[b.material]));
        }
        Object io = a;
        io.name = fmt::format("{}|{}", a.name, b.name);
        io.material = interface_material[key];
        io.mesh = uint32_t(s.meshes.size());
        s.meshes.push_back(sub_mesh(scene.meshes[a.mesh], take, io.name));
        s.objects.push_back(io);
    }
    // What stays of each object; an object all of whose faces left is gone.
    std::vector<bool> gone(s.objects.size(), false);
    for (uint32_t o : candidates) {
        std::vector<bool> keep = removed[o];
        keep.flip();
        if (std::find(keep.begin(), keep.end(), false) == keep.end()) continue; // untouched
        gone[o] = std::find(keep.begin(), keep.end(), true) == keep.end();
        if (gone[o]) continue;
        const Mesh& m = scene.meshes[scene.objects[o].mesh];
        s.objects[o].mesh = uint32_t(s.meshes.size());
        s.meshes.push_back(sub_mesh(m, keep, m.name));
    }
    std::vector<Object> objects;
    for (uint32_t o = 0; o < s.objects.size(); ++o)
        if (!gone[o]) objects.push_back(s.objects[o]);
    s.objects = std::move(objects);
    return out;
}

} // namespace tp
