#include "scene/obj_loader.h"

#include "image/texture_io.h"
#include "scene/text_parse.h"
#include "scene/texture_slots.h"
#include "shared/math.h"
#include "util/error.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>

namespace fs = std::filesystem;

namespace tp {
namespace {

// Statements that carry nothing twinpath renders; skipped without comment.
const std::set<std::string> kIgnoredObj = {"o", "g", "s", "mg", "l", "p", "vp", "cstype", "deg"};
const std::set<std::string> kIgnoredMtl = {"Ka",     "d",     "Tr",       "map_Ka", "map_Ks",
                                           "map_Ns", "map_d", "map_bump", "bump",   "disp",
                                           "decal",  "refl",  "sharpness"};

uint32_t add_texture(Scene& scene, const fs::path& file) {
    const std::string key = fs::weakly_canonical(file).string();
    for (size_t i = 0; i < scene.textures.size(); ++i)
        if (scene.textures[i].name == key) return uint32_t(i);
    Texture t = load_texture(file.string());
    t.name = key;
    scene.textures.push_back(std::move(t));
    return uint32_t(scene.textures.size() - 1);
}

// The file name of a map_* statement is its last token: options such as -s u v come first.
std::string map_file(const LineReader& in, const std::vector<std::string_view>& tok) {
    if (tok.size() < 2) in.fail("{} needs a file name", tok[0]);
    return std::string(tok.back());
}

void load_mtl(const fs::path& path, Scene& scene, std::map<std::string, uint32_t>& by_name,
              std::vector<std::string>& warnings) {
    LineReader in(path.string());
    std::map<std::string, int> ignored;
    Material* cur = nullptr;
    std::string cur_name;
    int illum = 2;
    size_t cur_line = 0;
    auto finish = [&]() {
        if (!cur) return;
        if (illum == 3)
            cur->type = MATERIAL_MIRROR;
        else if (illum == 7)
            cur->type = MATERIAL_DIELECTRIC;
        else if (illum < 0 || illum > 2)
            warnings.push_back(fmt::format("{}:{}: material '{}': illum {} is rendered as illum 2 "
                                           "(Phong); twinpath maps 3 to mirror and 7 to glass",
                                           path.string(), cur_line, cur_name, illum));
        validate_material(*cur,
                          fmt::format("{}:{}: material '{}'", path.string(), cur_line, cur_name));
    };
    std::vector<std::string_view> tok;
    while (in.next(tok)) {
        const std::string_view key = tok[0];
        if (key == "newmtl") {
            finish();
            if (tok.size() < 2) in.fail("newmtl needs a name");
            cur_name = in.rest_after(1);
            scene.materials.push_back(default_material());
            scene.material_names.push_back(cur_name);
            by_name[cur_name] = uint32_t(scene.materials.size() - 1);
            cur = &scene.materials.back();
            illum = 2;
            cur_line = in.line();
            continue;
        }
        if (kIgnoredMtl.count(std::string(key))) {
            ++ignored[std::string(key)];
            continue;
        }
        if (!cur) in.fail("'{}' before any newmtl", key);
        if (key == "Kd")
            cur->kd = in.color(tok);
        else if (key == "Ks")
            cur->ks = in.color(tok);
        else if (key == "Ke")
            cur->ke = in.color(tok);
        else if (key == "Tf")
            cur->tf = in.color(tok);
        else if (key == "Ns")
            cur->ns = in.number(tok, 1);
        else if (key == "Ni")
            cur->ior = in.number(tok, 1);
        else if (key == "illum")
            illum = int(in.integer(tok, 1));
        else if (key == "map_Kd") {
            const fs::path file = path.parent_path() / map_file(in, tok);
            if (!fs::exists(file)) in.fail("map_Kd texture '{}' does not exist", file.string());
            try {
                cur->kd_texture =
                    add_texture_slot(scene, obj_texture_slot(add_texture(scene, file), true));
            } catch (const InputError& e) {
                in.fail("map_Kd: {}", e.what()); // the texture's own error, at this line
            }
        } else
            in.fail("unknown MTL statement '{}'", key);
    }
    finish();
    if (!ignored.empty()) {
        std::string list;
        for (const auto& [k, n] : ignored)
            list += fmt::format("{}{} ({}x)", list.empty() ? "" : ", ", k, n);
        warnings.push_back(fmt::format("{}: ignored statements twinpath does not render: {}",
                                       path.string(), list));
    }
}

struct Corner {
    int v, vt, vn;
    bool operator<(const Corner& o) const {
        return std::tie(v, vt, vn) < std::tie(o.v, o.vt, o.vn);
    }
};

struct Group {
    uint32_t material;
    std::vector<std::array<Corner, 3>> triangles;
    std::vector<size_t> lines; // source line of each triangle, for error messages
};

// OBJ indices are 1-based; negative ones count back from the last element read so far.
int resolve_index(const LineReader& in, std::string_view s, size_t count, const char* what) {
    const long long i = in.parse_integer(s);
    long long r = i > 0 ? i - 1 : (i < 0 ? (long long)count + i : -1);
    if (i == 0) in.fail("{} index 0 is invalid (OBJ indices start at 1)", what);
    if (r < 0 || r >= (long long)count)
        in.fail("{} index {} is out of range: {} {}s defined so far", what, i, count, what);
    return int(r);
}

} // namespace

std::vector<ObjPart> load_obj(const std::string& path_str, Scene& scene, uint32_t default_mat,
                              std::vector<std::string>& warnings) {
    const fs::path path(path_str);
    LineReader in(path_str);
    std::vector<glm::dvec3> v;
    std::vector<vec3> vn;
    std::vector<vec2> vt;
    std::map<std::string, uint32_t> materials;
    std::vector<Group> groups;
    std::map<uint32_t, size_t> group_of_material;
    uint32_t current = default_mat;
    auto group = [&]() -> Group& {
        auto it = group_of_material.find(current);
        if (it == group_of_material.end()) {
            groups.push_back(Group{current, {}, {}});
            it = group_of_material.emplace(current, groups.size() - 1).first;
        }
        return groups[it->second];
    };

    std::vector<std::string_view> tok;
    while (in.next(tok)) {
        const std::string_view key = tok[0];
        if (key == "v") {
            if (tok.size() != 4 && tok.size() != 5)
                in.fail("'v' needs 3 coordinates (and an optional w)");
            const glm::dvec3 p = in.position_at(tok, 1);
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                in.fail("vertex position is not finite");
            v.push_back(p);
        } else if (key == "vt") {
            if (tok.size() < 2 || tok.size() > 4) in.fail("'vt' needs 1 to 3 coordinates");
            vt.push_back(vec2(in.number(tok, 1), tok.size() > 2 ? in.number(tok, 2) : 0.0f));
        } else if (key == "vn") {
            if (tok.size() != 4) in.fail("'vn' needs 3 coordinates");
            vn.push_back(in.vec3_at(tok, 1));
        } else if (key == "f") {
            if (tok.size() < 4) in.fail("a face needs at least 3 vertices, got {}", tok.size() - 1);
            std::vector<Corner> poly;
            for (size_t i = 1; i < tok.size(); ++i) {
                const std::string_view c = tok[i];
                const size_t s1 = c.find('/');
                const size_t s2 = s1 == std::string_view::npos ? s1 : c.find('/', s1 + 1);
                Corner k{-1, -1, -1};
                k.v = resolve_index(in, c.substr(0, s1), v.size(), "vertex");
                if (s1 != std::string_view::npos) {
                    const std::string_view t =
                        c.substr(s1 + 1, s2 == std::string_view::npos ? s2 : s2 - s1 - 1);
                    if (!t.empty()) k.vt = resolve_index(in, t, vt.size(), "texture coordinate");
                    if (s2 != std::string_view::npos)
                        k.vn = resolve_index(in, c.substr(s2 + 1), vn.size(), "normal");
                }
                poly.push_back(k);
            }
            Group& g = group();
            for (size_t i = 1; i + 1 < poly.size(); ++i) { // fan triangulation
                g.triangles.push_back({poly[0], poly[i], poly[i + 1]});
                g.lines.push_back(in.line());
            }
        } else if (key == "usemtl") {
            if (tok.size() < 2) in.fail("usemtl needs a material name");
            const std::string name = in.rest_after(1);
            auto it = materials.find(name);
            if (it == materials.end())
                in.fail("material '{}' is not defined by any mtllib before it", name);
            current = it->second;
        } else if (key == "mtllib") {
            if (tok.size() < 2) in.fail("mtllib needs a file name");
            const fs::path mtl = path.parent_path() / in.rest_after(1);
            if (!fs::exists(mtl)) in.fail("material library '{}' does not exist", mtl.string());
            load_mtl(mtl, scene, materials, warnings);
        } else if (!kIgnoredObj.count(std::string(key))) {
            in.fail("unknown OBJ statement '{}'", key);
        }
    }

    std::vector<ObjPart> parts;
    const std::string stem = path.stem().string();
    for (const Group& g : groups) {
        // A group keeps normals (uvs) only if every corner has one; indices are unified so
        // that one index addresses position, normal and uv alike.
        bool all_vn = true, all_vt = true;
        for (const auto& tri : g.triangles)
            for (const Corner& c : tri) {
                all_vn = all_vn && c.vn >= 0;
                all_vt = all_vt && c.vt >= 0;
            }
        Mesh m;
        m.name = groups.size() == 1
                     ? stem
                     : fmt::format("{}:{}", stem, scene.material_names.at(g.material));
        std::map<Corner, uint32_t> index;
        for (const auto& tri : g.triangles) {
            uvec3 out;
            for (int k = 0; k < 3; ++k) {
                Corner c = tri[k];
                if (!all_vn) c.vn = -1;
                if (!all_vt) c.vt = -1;
                auto [it, inserted] = index.emplace(c, uint32_t(m.positions.size()));
                if (inserted) {
                    m.positions.push_back(v[c.v]);
                    if (all_vn) m.normals.push_back(vn[c.vn]);
                    if (all_vt) m.uvs.push_back(vt[c.vt]);
                }
                out[k] = it->second;
            }
            m.triangles.push_back(out);
        }
        finalize_mesh(m, path_str, scene.skipped_triangles);
        if (m.triangles.empty()) continue;
        scene.meshes.push_back(std::move(m));
        parts.push_back(ObjPart{uint32_t(scene.meshes.size() - 1), g.material});
    }
    if (parts.empty()) input_error("{}: no triangles", path_str);
    return parts;
}

} // namespace tp
