#include "scene/gltf_document.h"

#include "scene/json_reader.h"
#include "scene/text_parse.h"
#include "util/error.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace tp {
namespace {

using json = nlohmann::json;

// JsonReader plus what glTF needs: optional members, indices into the document's arrays,
// numbers in double with a range, fixed-length number arrays.
class Reader {
  public:
    explicit Reader(const std::string& path) : r_(path) {}

    [[noreturn]] void fail(const std::string& field, const std::string& what) const {
        r_.fail(field, what);
    }

    static std::string at(const std::string& field, const char* key) { return field + "." + key; }
    static std::string at(const std::string& field, size_t i) {
        return fmt::format("{}[{}]", field, i);
    }

    // The member `key` of the object j, or nullptr.
    static const json* find(const json& j, const char* key) {
        const auto it = j.find(key);
        return it == j.end() ? nullptr : &*it;
    }

    const json& object(const json& j, const std::string& field) const {
        if (!j.is_object()) fail(field, "expected an object");
        return j;
    }
    const json& array(const json& j, const std::string& field) const {
        if (!j.is_array()) fail(field, "expected an array");
        return j;
    }
    const json& required(const json& j, const std::string& field, const char* key) const {
        const json* v = find(j, key);
        if (!v) fail(at(field, key), "is required");
        return *v;
    }

    uint64_t integer(const json& j, const std::string& field, uint64_t lo, uint64_t hi) const {
        if (!j.is_number_integer())
            fail(field, fmt::format("expected an integer, got {}", dump(j)));
        if (!j.is_number_unsigned() || j.get<uint64_t>() < lo || j.get<uint64_t>() > hi)
            fail(field, fmt::format("must lie in [{}, {}], got {}", lo, hi, dump(j)));
        return j.get<uint64_t>();
    }

    // An index into the document's array `what` of `n` elements.
    uint32_t index(const json& j, const std::string& field, size_t n, const char* what) const {
        if (!j.is_number_integer() || !j.is_number_unsigned() || j.get<uint64_t>() >= n)
            fail(field,
                 n == 0
                     ? fmt::format("{} names an element of '{}', which is empty or absent", dump(j),
                                   what)
                     : fmt::format("{} is not an index into '{}' (0 to {})", dump(j), what, n - 1));
        return uint32_t(j.get<uint64_t>());
    }

    double number(const json& j, const std::string& field, double lo, double hi) const {
        const double v = r_.coordinate(j, field); // finite and within float's range
        if (v < lo || v > hi) fail(field, fmt::format("must lie in [{}, {}], got {}", lo, hi, v));
        return v;
    }
    double number(const json& j, const std::string& field) const { return r_.coordinate(j, field); }

    std::vector<double> numbers(const json& j, const std::string& field, size_t n, double lo,
                                double hi) const {
        if (!j.is_array() || j.size() != n) fail(field, fmt::format("expected {} numbers", n));
        std::vector<double> v(n);
        for (size_t i = 0; i < n; ++i) v[i] = number(j[i], at(field, i), lo, hi);
        return v;
    }

    std::string string(const json& j, const std::string& field) const {
        return r_.string(j, field);
    }
    bool boolean(const json& j, const std::string& field) const { return r_.boolean(j, field); }

    std::string name(const json& j, const std::string& field) const {
        const json* n = find(j, "name");
        return n ? clip(string(*n, at(field, "name"))) : std::string();
    }

    // Members of `extensions` of j (an object when present).
    std::vector<std::string> extension_names(const json& j, const std::string& field) const {
        std::vector<std::string> out;
        if (const json* e = find(j, "extensions"))
            for (const auto& item : object(*e, at(field, "extensions")).items())
                out.push_back(item.key());
        return out;
    }
    const json* extension(const json& j, const std::string& field, const char* name) const {
        const json* e = find(j, "extensions");
        if (!e) return nullptr;
        const json* x = find(object(*e, at(field, "extensions")), name);
        return x ? &object(*x, at(at(field, "extensions"), name)) : nullptr;
    }

    static std::string dump(const json& j) { return clip(j.dump()); }

  private:
    JsonReader r_;
};

constexpr double kMax = 3.4e38; // float's range: numbers beyond are errors (scene-format.md)
constexpr uint32_t kMaxZeroAccessor = 1u << 20;

// The elements of the top-level array `key`, each an object.
const json& top_array(const Reader& r, const json& root, const char* key) {
    static const json empty = json::array();
    const json* a = Reader::find(root, key);
    if (!a) return empty;
    r.array(*a, key);
    for (size_t i = 0; i < a->size(); ++i) r.object((*a)[i], Reader::at(key, i));
    return *a;
}

uint32_t components_of(const Reader& r, const std::string& type, const std::string& field) {
    static const std::pair<const char*, uint32_t> kTypes[] = {
        {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
        {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
    for (const auto& [name, n] : kTypes)
        if (type == name) return n;
    r.fail(field, fmt::format("unknown accessor type '{}' (expected SCALAR, VEC2, VEC3, VEC4, "
                              "MAT2, MAT3 or MAT4)",
                              clip(type)));
}

// Bytes of one element: a matrix's columns each start at a multiple of 4 bytes (spec 3.6.2.4).
uint64_t element_size(const GltfAccessor& a) {
    const uint64_t c = gltf_component_size(a.component_type);
    if (a.type.rfind("MAT", 0) != 0) return a.components * c;
    const uint64_t n = a.type == "MAT2" ? 2 : a.type == "MAT3" ? 3 : 4;
    return n * ((n * c + 3) / 4 * 4);
}

// `bytes` bytes at `offset` of buffer view v must lie inside it.
void check_in_view(const Reader& r, const GltfDocument& d, int v, uint64_t offset, uint64_t bytes,
                   const std::string& field, const char* what) {
    const GltfBufferView& view = d.buffer_views[size_t(v)];
    if (offset > view.byte_length || bytes > view.byte_length - offset)
        r.fail(field, fmt::format("{} needs bytes {} to {} of bufferViews[{}], which has {}", what,
                                  offset, offset + bytes, v, view.byte_length));
}

GltfTextureRef read_texture_ref(const Reader& r, const json& j, const std::string& field,
                                size_t textures) {
    GltfTextureRef t;
    t.field = field;
    r.object(j, field);
    t.texture = int(
        r.index(r.required(j, field, "index"), Reader::at(field, "index"), textures, "textures"));
    if (const json* tc = Reader::find(j, "texCoord"))
        t.tex_coord = uint32_t(r.integer(*tc, Reader::at(field, "texCoord"), 0, 1u << 30));
    if (const json* x = r.extension(j, field, "KHR_texture_transform")) {
        const std::string f = Reader::at(Reader::at(field, "extensions"), "KHR_texture_transform");
        glm::dvec2 offset(0.0), scale(1.0);
        double rotation = 0.0;
        if (const json* o = Reader::find(*x, "offset")) {
            const std::vector<double> v = r.numbers(*o, Reader::at(f, "offset"), 2, -kMax, kMax);
            offset = {v[0], v[1]};
        }
        if (const json* s = Reader::find(*x, "scale")) {
            const std::vector<double> v = r.numbers(*s, Reader::at(f, "scale"), 2, -kMax, kMax);
            scale = {v[0], v[1]};
        }
        if (const json* a = Reader::find(*x, "rotation"))
            rotation = r.number(*a, Reader::at(f, "rotation"));
        if (const json* tc = Reader::find(*x, "texCoord"))
            t.tex_coord = uint32_t(r.integer(*tc, Reader::at(f, "texCoord"), 0, 1u << 30));
        // The extension's matrix, translation * rotation * scale (KHR_texture_transform,
        // "Overview"), with the rotation (u, v) -> (c u + s v, -s u + c v): counter-clockwise
        // in glTF's uv space, whose v points down. The extension's GLSL listing writes that
        // rotation transposed; its own example (offset (0, 1), rotation pi/2, scale 0.5: the
        // image's lower-left quadrant), its sample model TextureTransformTest and the
        // implementations (Khronos' glTF-Sample-Viewer, three.js, Babylon.js, Blender) all
        // rotate this way. Column by column, as glm stores it.
        const double c = std::cos(rotation), s = std::sin(rotation);
        const glm::dmat3 T(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
        const glm::dmat3 R(c, -s, 0, s, c, 0, 0, 0, 1);
        const glm::dmat3 S(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
        t.transform = T * R * S;
    }
    return t;
}

// Three numbers in [lo, hi] as a colour.
vec3 read_color(const Reader& r, const json& j, const std::string& field, double lo, double hi) {
    const std::vector<double> v = r.numbers(j, field, 3, lo, hi);
    return vec3(float(v[0]), float(v[1]), float(v[2]));
}

// The textureInfo `key` of object j, if given.
void read_texture_slot(const Reader& r, const json& j, const std::string& field, const char* key,
                       size_t textures, GltfTextureRef& out) {
    if (const json* t = Reader::find(j, key))
        out = read_texture_ref(r, *t, Reader::at(field, key), textures);
}

void read_pbr_metallic_roughness(const Reader& r, const json& j, const std::string& field,
                                 size_t textures, GltfMaterial& m) {
    r.object(j, field);
    if (const json* c = Reader::find(j, "baseColorFactor")) {
        const std::vector<double> v = r.numbers(*c, Reader::at(field, "baseColorFactor"), 4, 0, 1);
        m.base_color = vec3(float(v[0]), float(v[1]), float(v[2]));
        m.base_alpha = float(v[3]);
    }
    read_texture_slot(r, j, field, "baseColorTexture", textures, m.base_color_texture);
    if (const json* v = Reader::find(j, "metallicFactor"))
        m.metallic = float(r.number(*v, Reader::at(field, "metallicFactor"), 0, 1));
    if (const json* v = Reader::find(j, "roughnessFactor"))
        m.roughness = float(r.number(*v, Reader::at(field, "roughnessFactor"), 0, 1));
    read_texture_slot(r, j, field, "metallicRoughnessTexture", textures,
                      m.metallic_roughness_texture);
}

// The material extensions twinpath reads; any other is listed as unused.
void read_material_extension(const Reader& r, const json& x, const std::string& name,
                             const std::string& f, size_t textures, GltfMaterial& m) {
    if (name == "KHR_materials_emissive_strength") {
        if (const json* s = Reader::find(x, "emissiveStrength"))
            m.emissive_strength = float(r.number(*s, Reader::at(f, "emissiveStrength"), 0, kMax));
    } else if (name == "KHR_materials_transmission") {
        if (const json* t = Reader::find(x, "transmissionFactor"))
            m.transmission = float(r.number(*t, Reader::at(f, "transmissionFactor"), 0, 1));
        read_texture_slot(r, x, f, "transmissionTexture", textures, m.transmission_texture);
    } else if (name == "KHR_materials_ior") {
        if (const json* i = Reader::find(x, "ior")) {
            const std::string fi = Reader::at(f, "ior");
            m.ior = float(r.number(*i, fi, 0, kMax));
            if (m.ior != 0.0f && m.ior < 1.0f)
                r.fail(fi, fmt::format("must be 0 or at least 1, got {}", m.ior));
        }
    } else if (name == "KHR_materials_specular") {
        if (const json* s = Reader::find(x, "specularFactor"))
            m.specular = float(r.number(*s, Reader::at(f, "specularFactor"), 0, 1));
        if (const json* c = Reader::find(x, "specularColorFactor"))
            m.specular_color = read_color(r, *c, Reader::at(f, "specularColorFactor"), 0, kMax);
        read_texture_slot(r, x, f, "specularTexture", textures, m.specular_texture);
        read_texture_slot(r, x, f, "specularColorTexture", textures, m.specular_color_texture);
    } else if (name == "KHR_materials_volume") {
        if (const json* t = Reader::find(x, "thicknessFactor"))
            m.thickness = float(r.number(*t, Reader::at(f, "thicknessFactor"), 0, kMax));
        if (const json* t = Reader::find(x, "thicknessTexture")) {
            read_texture_ref(r, *t, Reader::at(f, "thicknessTexture"), textures);
            m.ignored.push_back("KHR_materials_volume.thicknessTexture");
        }
        if (const json* c = Reader::find(x, "attenuationColor"))
            m.attenuation_color = read_color(r, *c, Reader::at(f, "attenuationColor"), 0, 1);
        if (const json* d = Reader::find(x, "attenuationDistance")) {
            const std::string fd = Reader::at(f, "attenuationDistance");
            m.attenuation_distance = float(r.number(*d, fd, 0, kMax));
            if (!(m.attenuation_distance > 0.0f)) r.fail(fd, "must be greater than 0");
        }
    } else {
        m.unused.push_back(clip(name));
    }
}

GltfMaterial read_material(const Reader& r, const json& j, const std::string& field,
                           size_t textures) {
    GltfMaterial m;
    m.name = r.name(j, field);
    if (const json* pbr = Reader::find(j, "pbrMetallicRoughness"))
        read_pbr_metallic_roughness(r, *pbr, Reader::at(field, "pbrMetallicRoughness"), textures,
                                    m);
    read_texture_slot(r, j, field, "normalTexture", textures, m.normal_texture);
    if (const json* n = Reader::find(j, "normalTexture"))
        if (const json* s = Reader::find(*n, "scale"))
            m.normal_scale =
                float(r.number(*s, Reader::at(Reader::at(field, "normalTexture"), "scale")));
    if (const json* t = Reader::find(j, "occlusionTexture")) {
        const std::string f = Reader::at(field, "occlusionTexture");
        read_texture_ref(r, *t, f, textures);
        if (const json* s = Reader::find(*t, "strength"))
            r.number(*s, Reader::at(f, "strength"), 0, 1);
        m.ignored.push_back("occlusionTexture");
    }
    if (const json* e = Reader::find(j, "emissiveFactor"))
        m.emissive = read_color(r, *e, Reader::at(field, "emissiveFactor"), 0, 1);
    read_texture_slot(r, j, field, "emissiveTexture", textures, m.emissive_texture);
    if (const json* a = Reader::find(j, "alphaMode")) {
        m.alpha_mode = r.string(*a, Reader::at(field, "alphaMode"));
        if (m.alpha_mode != "OPAQUE" && m.alpha_mode != "MASK" && m.alpha_mode != "BLEND")
            r.fail(Reader::at(field, "alphaMode"),
                   fmt::format("'{}' is not OPAQUE, MASK or BLEND", clip(m.alpha_mode)));
    }
    if (const json* c = Reader::find(j, "alphaCutoff"))
        m.alpha_cutoff = float(r.number(*c, Reader::at(field, "alphaCutoff"), 0, kMax));
    if (const json* d = Reader::find(j, "doubleSided"))
        r.boolean(*d, Reader::at(field, "doubleSided"));
    for (const std::string& name : r.extension_names(j, field))
        read_material_extension(r, *r.extension(j, field, name.c_str()), name,
                                Reader::at(Reader::at(field, "extensions"), name.c_str()), textures,
                                m);
    return m;
}

glm::dmat4 read_node_transform(const Reader& r, const json& j, const std::string& field) {
    const json* matrix = Reader::find(j, "matrix");
    const json* t = Reader::find(j, "translation");
    const json* q = Reader::find(j, "rotation");
    const json* s = Reader::find(j, "scale");
    if (matrix) {
        if (t || q || s)
            r.fail(field, "has both a matrix and translation/rotation/scale (spec 5.25: "
                          "they are exclusive)");
        const std::vector<double> v =
            r.numbers(*matrix, Reader::at(field, "matrix"), 16, -kMax, kMax);
        // Column-major, as glm: element (row, col) is v[col * 4 + row].
        if (v[3] != 0.0 || v[7] != 0.0 || v[11] != 0.0 || v[15] != 1.0)
            r.fail(Reader::at(field, "matrix"),
                   "its last row must be 0 0 0 1 (an affine transform; glTF matrices are "
                   "column-major)");
        return glm::make_mat4(v.data());
    }
    glm::dmat4 m(1.0);
    if (t) {
        const std::vector<double> v =
            r.numbers(*t, Reader::at(field, "translation"), 3, -kMax, kMax);
        m[3] = glm::dvec4(v[0], v[1], v[2], 1.0);
    }
    if (q) {
        const std::vector<double> v = r.numbers(*q, Reader::at(field, "rotation"), 4, -1, 1);
        const glm::dquat rot(v[3], v[0], v[1], v[2]); // glTF stores x, y, z, w
        const double len = glm::length(rot);
        // Exporters write unit quaternions to float precision; a quaternion far from unit
        // length is not a rotation.
        if (std::abs(len - 1.0) > 1e-3)
            r.fail(Reader::at(field, "rotation"),
                   fmt::format("must be a unit quaternion, its length is {}", len));
        m = m * glm::mat4_cast(rot / len);
    }
    if (s) {
        const std::vector<double> v = r.numbers(*s, Reader::at(field, "scale"), 3, -kMax, kMax);
        m = m * glm::dmat4(glm::dvec4(v[0], 0, 0, 0), glm::dvec4(0, v[1], 0, 0),
                           glm::dvec4(0, 0, v[2], 0), glm::dvec4(0, 0, 0, 1));
    }
    return m;
}

std::vector<std::string> string_list(const Reader& r, const json& root, const char* key) {
    std::vector<std::string> out;
    if (const json* a = Reader::find(root, key))
        for (size_t i = 0; i < r.array(*a, key).size(); ++i)
            out.push_back(r.string((*a)[i], Reader::at(key, i)));
    return out;
}

void read_asset(const Reader& r, const json& root) {
    const json& asset = r.object(r.required(root, "", "asset"), "asset");
    const std::string version = r.string(r.required(asset, "asset", "version"), "asset.version");
    if (version.rfind("2.", 0) != 0)
        r.fail("asset.version", fmt::format("'{}': twinpath reads glTF 2.x", clip(version)));
    if (const json* mv = Reader::find(asset, "minVersion")) {
        const std::string min = r.string(*mv, "asset.minVersion");
        if (min != "2.0")
            r.fail("asset.minVersion",
                   fmt::format("'{}': twinpath implements glTF 2.0", clip(min)));
    }
}

void read_extensions(const Reader& r, const json& root, GltfDocument& d) {
    d.extensions_used = string_list(r, root, "extensionsUsed");
    d.extensions_required = string_list(r, root, "extensionsRequired");
    const std::vector<std::string>& supported = gltf_supported_extensions();
    for (size_t i = 0; i < d.extensions_required.size(); ++i) {
        const std::string& e = d.extensions_required[i];
        if (std::find(supported.begin(), supported.end(), e) == supported.end()) {
            std::string list;
            for (const std::string& s : supported) list += (list.empty() ? "" : ", ") + s;
            r.fail(Reader::at("extensionsRequired", i),
                   fmt::format("extension '{}' is required to load this asset and twinpath does "
                               "not support it (it reads {})",
                               clip(e), list));
        }
    }
}

void read_buffers(const Reader& r, const json& root, bool is_glb, GltfDocument& d) {
    const json& buffers = top_array(r, root, "buffers");
    for (size_t i = 0; i < buffers.size(); ++i) {
        const std::string f = Reader::at("buffers", i);
        GltfBuffer b;
        b.byte_length = r.integer(r.required(buffers[i], f, "byteLength"),
                                  Reader::at(f, "byteLength"), 1, uint64_t(1) << 53);
        if (const json* u = Reader::find(buffers[i], "uri"))
            b.uri = r.string(*u, Reader::at(f, "uri"));
        if (b.uri.empty() && !(is_glb && i == 0))
            r.fail(Reader::at(f, "uri"),
                   "is required (only buffer 0 of a .glb file may omit it: the BIN chunk)");
        d.buffers.push_back(b);
    }
    const json& views = top_array(r, root, "bufferViews");
    for (size_t i = 0; i < views.size(); ++i) {
        const std::string f = Reader::at("bufferViews", i);
        const json& j = views[i];
        GltfBufferView v;
        v.buffer = r.index(r.required(j, f, "buffer"), Reader::at(f, "buffer"), d.buffers.size(),
                           "buffers");
        v.byte_length = r.integer(r.required(j, f, "byteLength"), Reader::at(f, "byteLength"), 1,
                                  uint64_t(1) << 53);
        if (const json* o = Reader::find(j, "byteOffset"))
            v.byte_offset = r.integer(*o, Reader::at(f, "byteOffset"), 0, uint64_t(1) << 53);
        if (const json* s = Reader::find(j, "byteStride")) {
            v.byte_stride = uint32_t(r.integer(*s, Reader::at(f, "byteStride"), 4, 252));
            if (v.byte_stride % 4 != 0)
                r.fail(Reader::at(f, "byteStride"),
                       fmt::format("must be a multiple of 4, got {}", v.byte_stride));
        }
        const uint64_t size = d.buffers[v.buffer].byte_length;
        if (v.byte_offset > size || v.byte_length > size - v.byte_offset)
            r.fail(f, fmt::format("byteOffset {} + byteLength {} runs past the end of buffers[{}] "
                                  "(byteLength {})",
                                  v.byte_offset, v.byte_length, v.buffer, size));
        d.buffer_views.push_back(v);
    }
}

void read_accessors(const Reader& r, const json& root, GltfDocument& d) {
    const json& accessors = top_array(r, root, "accessors");
    for (size_t i = 0; i < accessors.size(); ++i) {
        const std::string f = Reader::at("accessors", i);
        const json& j = accessors[i];
        GltfAccessor a;
        a.component_type = uint32_t(r.integer(r.required(j, f, "componentType"),
                                              Reader::at(f, "componentType"), 0, 1u << 30));
        if (gltf_component_size(a.component_type) == 0)
            r.fail(Reader::at(f, "componentType"),
                   fmt::format("{} is not a glTF component type (5120, 5121, 5122, 5123, 5125, "
                               "5126)",
                               a.component_type));
        a.count =
            uint32_t(r.integer(r.required(j, f, "count"), Reader::at(f, "count"), 1, 0xFFFFFFFFu));
        a.type = r.string(r.required(j, f, "type"), Reader::at(f, "type"));
        a.components = components_of(r, a.type, Reader::at(f, "type"));
        if (const json* n = Reader::find(j, "normalized")) {
            a.normalized = r.boolean(*n, Reader::at(f, "normalized"));
            if (a.normalized &&
                (a.component_type == GLTF_FLOAT || a.component_type == GLTF_UNSIGNED_INT))
                r.fail(Reader::at(f, "normalized"),
                       "only byte and short components can be normalized");
        }
        if (const json* o = Reader::find(j, "byteOffset"))
            a.byte_offset = r.integer(*o, Reader::at(f, "byteOffset"), 0, uint64_t(1) << 53);
        const uint64_t element = element_size(a);
        if (const json* v = Reader::find(j, "bufferView")) {
            a.buffer_view =
                int(r.index(*v, Reader::at(f, "bufferView"), d.buffer_views.size(), "bufferViews"));
            const GltfBufferView& view = d.buffer_views[size_t(a.buffer_view)];
            if (view.byte_stride != 0 && view.byte_stride < element)
                r.fail(f, fmt::format("its elements have {} bytes, more than the byteStride {} "
                                      "of bufferViews[{}]",
                                      element, view.byte_stride, a.buffer_view));
            const uint64_t stride = view.byte_stride != 0 ? view.byte_stride : element;
            check_in_view(r, d, a.buffer_view, a.byte_offset, stride * (a.count - 1) + element, f,
                          fmt::format("{} elements of {} bytes at byteOffset {}", a.count, element,
                                      a.byte_offset)
                              .c_str());
        } else if (a.byte_offset != 0) {
            r.fail(Reader::at(f, "byteOffset"), "is given without a bufferView");
        } else if (a.count > kMaxZeroAccessor) {
            // Without a buffer view the elements are zeros that the file does not hold: a few
            // bytes of JSON must not make the loader allocate gigabytes.
            r.fail(Reader::at(f, "count"),
                   fmt::format("{} elements without a bufferView (zeros, sparse or not): twinpath "
                               "reads at most {}",
                               a.count, kMaxZeroAccessor));
        }
        if (const json* s = Reader::find(j, "sparse")) {
            const std::string sf = Reader::at(f, "sparse");
            r.object(*s, sf);
            a.sparse_count = uint32_t(
                r.integer(r.required(*s, sf, "count"), Reader::at(sf, "count"), 1, a.count));
            const std::string fi = Reader::at(sf, "indices"), fv = Reader::at(sf, "values");
            const json& ji = r.object(r.required(*s, sf, "indices"), fi);
            const json& jv = r.object(r.required(*s, sf, "values"), fv);
            a.sparse_indices_view =
                int(r.index(r.required(ji, fi, "bufferView"), Reader::at(fi, "bufferView"),
                            d.buffer_views.size(), "bufferViews"));
            if (const json* o = Reader::find(ji, "byteOffset"))
                a.sparse_indices_offset =
                    r.integer(*o, Reader::at(fi, "byteOffset"), 0, uint64_t(1) << 53);
            a.sparse_indices_type = uint32_t(r.integer(
                r.required(ji, fi, "componentType"), Reader::at(fi, "componentType"), 0, 1u << 30));
            if (a.sparse_indices_type != GLTF_UNSIGNED_BYTE &&
                a.sparse_indices_type != GLTF_UNSIGNED_SHORT &&
                a.sparse_indices_type != GLTF_UNSIGNED_INT)
                r.fail(Reader::at(fi, "componentType"),
                       fmt::format("{} is not 5121, 5123 or 5125", a.sparse_indices_type));
            a.sparse_values_view =
                int(r.index(r.required(jv, fv, "bufferView"), Reader::at(fv, "bufferView"),
                            d.buffer_views.size(), "bufferViews"));
            if (const json* o = Reader::find(jv, "byteOffset"))
                a.sparse_values_offset =
                    r.integer(*o, Reader::at(fv, "byteOffset"), 0, uint64_t(1) << 53);
            check_in_view(r, d, a.sparse_indices_view, a.sparse_indices_offset,
                          uint64_t(a.sparse_count) * gltf_component_size(a.sparse_indices_type), fi,
                          "the sparse indices");
            check_in_view(r, d, a.sparse_values_view, a.sparse_values_offset,
                          uint64_t(a.sparse_count) * element, fv, "the sparse values");
        }
        d.accessors.push_back(a);
    }
}

void read_images_and_textures(const Reader& r, const json& root, GltfDocument& d) {
    const json& images = top_array(r, root, "images");
    for (size_t i = 0; i < images.size(); ++i) {
        const std::string f = Reader::at("images", i);
        GltfImage img;
        const json* uri = Reader::find(images[i], "uri");
        const json* view = Reader::find(images[i], "bufferView");
        if (bool(uri) == bool(view)) r.fail(f, "needs exactly one of 'uri' and 'bufferView'");
        if (uri) img.uri = r.string(*uri, Reader::at(f, "uri"));
        if (view)
            img.buffer_view = int(
                r.index(*view, Reader::at(f, "bufferView"), d.buffer_views.size(), "bufferViews"));
        if (const json* m = Reader::find(images[i], "mimeType"))
            img.mime_type = r.string(*m, Reader::at(f, "mimeType"));
        else if (view)
            r.fail(Reader::at(f, "mimeType"), "is required with a bufferView");
        d.images.push_back(img);
    }
    const json& samplers = top_array(r, root, "samplers");
    for (size_t i = 0; i < samplers.size(); ++i) {
        const std::string f = Reader::at("samplers", i);
        GltfSampler s;
        const std::pair<const char*, uint32_t*> fields[] = {{"magFilter", &s.mag_filter},
                                                            {"minFilter", &s.min_filter},
                                                            {"wrapS", &s.wrap_s},
                                                            {"wrapT", &s.wrap_t}};
        for (const auto& [key, out] : fields)
            if (const json* v = Reader::find(samplers[i], key))
                *out = uint32_t(r.integer(*v, Reader::at(f, key), 0, 1u << 30));
        // The values the specification allows (section 5.26).
        if (s.mag_filter != 0 && s.mag_filter != GLTF_NEAREST && s.mag_filter != GLTF_LINEAR)
            r.fail(Reader::at(f, "magFilter"),
                   fmt::format("{} is not 9728 (NEAREST) or 9729 (LINEAR)", s.mag_filter));
        if (s.min_filter != 0 && s.min_filter != GLTF_NEAREST && s.min_filter != GLTF_LINEAR &&
            (s.min_filter < 9984 || s.min_filter > 9987))
            r.fail(Reader::at(f, "minFilter"),
                   fmt::format("{} is not 9728, 9729 or 9984 to 9987", s.min_filter));
        for (const auto& [key, wrap] : {std::pair("wrapS", s.wrap_s), std::pair("wrapT", s.wrap_t)})
            if (wrap != GLTF_REPEAT && wrap != GLTF_CLAMP_TO_EDGE && wrap != GLTF_MIRRORED_REPEAT)
                r.fail(Reader::at(f, key),
                       fmt::format("{} is not 10497 (REPEAT), 33071 (CLAMP_TO_EDGE) or 33648 "
                                   "(MIRRORED_REPEAT)",
                                   wrap));
        d.samplers.push_back(s);
    }
    const json& textures = top_array(r, root, "textures");
    for (size_t i = 0; i < textures.size(); ++i) {
        const std::string f = Reader::at("textures", i);
        GltfTexture t;
        if (const json* s = Reader::find(textures[i], "source"))
            t.source = int(r.index(*s, Reader::at(f, "source"), d.images.size(), "images"));
        if (const json* s = Reader::find(textures[i], "sampler"))
            t.sampler = int(r.index(*s, Reader::at(f, "sampler"), d.samplers.size(), "samplers"));
        t.source_extensions = r.extension_names(textures[i], f);
        d.textures.push_back(t);
    }
}

void read_meshes(const Reader& r, const json& root, GltfDocument& d) {
    const json& meshes = top_array(r, root, "meshes");
    for (size_t i = 0; i < meshes.size(); ++i) {
        const std::string f = Reader::at("meshes", i);
        GltfMesh m;
        m.name = r.name(meshes[i], f);
        const std::string fp = Reader::at(f, "primitives");
        const json& prims = r.array(r.required(meshes[i], f, "primitives"), fp);
        if (prims.empty()) r.fail(fp, "must not be empty");
        for (size_t k = 0; k < prims.size(); ++k) {
            const std::string pf = Reader::at(fp, k);
            const json& pj = r.object(prims[k], pf);
            GltfPrimitive p;
            const std::string af = Reader::at(pf, "attributes");
            for (const auto& item : r.object(r.required(pj, pf, "attributes"), af).items())
                p.attributes[item.key()] = r.index(item.value(), Reader::at(af, item.key().c_str()),
                                                   d.accessors.size(), "accessors");
            if (const json* v = Reader::find(pj, "indices"))
                p.indices =
                    int(r.index(*v, Reader::at(pf, "indices"), d.accessors.size(), "accessors"));
            if (const json* v = Reader::find(pj, "material"))
                p.material =
                    int(r.index(*v, Reader::at(pf, "material"), d.materials.size(), "materials"));
            if (const json* v = Reader::find(pj, "mode"))
                p.mode = uint32_t(r.integer(*v, Reader::at(pf, "mode"), 0, 6));
            if (const json* t = Reader::find(pj, "targets"))
                p.morph_targets = !r.array(*t, Reader::at(pf, "targets")).empty();
            m.primitives.push_back(std::move(p));
        }
        d.meshes.push_back(std::move(m));
    }
}

// KHR_lights_punctual's spot: 0 <= innerConeAngle < outerConeAngle <= pi / 2.
void read_spot_cone(const Reader& r, const json& j, const std::string& field, GltfLight& l) {
    r.object(j, field);
    constexpr double kHalfPi = 1.5707963267948966;
    const std::string fi = Reader::at(field, "innerConeAngle"),
                      fo = Reader::at(field, "outerConeAngle");
    if (const json* v = Reader::find(j, "innerConeAngle"))
        l.inner_cone = float(r.number(*v, fi, 0, kHalfPi));
    if (const json* v = Reader::find(j, "outerConeAngle")) {
        l.outer_cone = float(r.number(*v, fo, 0, kHalfPi));
        if (!(l.outer_cone > 0.0f)) r.fail(fo, "must be greater than 0");
    }
    if (!(l.inner_cone < l.outer_cone))
        r.fail(fi,
               fmt::format("{} must be less than outerConeAngle {}", l.inner_cone, l.outer_cone));
}

void read_cameras_and_lights(const Reader& r, const json& root, GltfDocument& d) {
    const json& cameras = top_array(r, root, "cameras");
    for (size_t i = 0; i < cameras.size(); ++i) {
        const std::string f = Reader::at("cameras", i);
        GltfCamera c;
        c.name = r.name(cameras[i], f);
        const std::string type = r.string(r.required(cameras[i], f, "type"), Reader::at(f, "type"));
        if (type == "perspective") {
            const std::string pf = Reader::at(f, "perspective");
            const json& p = r.object(r.required(cameras[i], f, "perspective"), pf);
            c.yfov = r.number(r.required(p, pf, "yfov"), Reader::at(pf, "yfov"), 0, kMax);
            // The film's camera needs 0 < fov < 180 degrees.
            if (!(c.yfov > 0.0 && c.yfov < 3.14159))
                r.fail(Reader::at(pf, "yfov"),
                       fmt::format("must lie in (0, pi) radians, got {}", c.yfov));
            if (const json* a = Reader::find(p, "aspectRatio")) {
                c.aspect_ratio = r.number(*a, Reader::at(pf, "aspectRatio"), 0, kMax);
                if (!(c.aspect_ratio > 0.0))
                    r.fail(Reader::at(pf, "aspectRatio"), "must be greater than 0");
            }
            r.number(r.required(p, pf, "znear"), Reader::at(pf, "znear"), 0, kMax);
        } else if (type == "orthographic") {
            r.object(r.required(cameras[i], f, "orthographic"), Reader::at(f, "orthographic"));
            c.perspective = false;
        } else {
            r.fail(Reader::at(f, "type"),
                   fmt::format("'{}' is not perspective or orthographic", clip(type)));
        }
        d.cameras.push_back(c);
    }
    const json* lp = r.extension(root, "", "KHR_lights_punctual");
    if (!lp) return;
    const std::string lf = "extensions.KHR_lights_punctual.lights";
    const json* lights = Reader::find(*lp, "lights");
    if (!lights) return;
    for (size_t i = 0; i < r.array(*lights, lf).size(); ++i) {
        const std::string f = Reader::at(lf, i);
        const json& j = r.object((*lights)[i], f);
        GltfLight l;
        l.name = r.name(j, f);
        l.type = r.string(r.required(j, f, "type"), Reader::at(f, "type"));
        if (l.type != "point" && l.type != "spot" && l.type != "directional")
            r.fail(Reader::at(f, "type"),
                   fmt::format("'{}' is not point, spot or directional", clip(l.type)));
        if (const json* c = Reader::find(j, "color")) {
            const std::vector<double> v = r.numbers(*c, Reader::at(f, "color"), 3, 0, kMax);
            l.color = vec3(float(v[0]), float(v[1]), float(v[2]));
        }
        if (const json* v = Reader::find(j, "intensity"))
            l.intensity = float(r.number(*v, Reader::at(f, "intensity"), 0, kMax));
        if (const json* v = Reader::find(j, "range")) {
            if (!(r.number(*v, Reader::at(f, "range"), 0, kMax) > 0.0))
                r.fail(Reader::at(f, "range"), "must be greater than 0");
            l.has_range = true;
        }
        if (l.type == "spot") {
            static const json none = json::object(); // the cones' defaults
            const json* spot = Reader::find(j, "spot");
            read_spot_cone(r, spot ? *spot : none, Reader::at(f, "spot"), l);
        }
        d.lights.push_back(l);
    }
}

void read_nodes_and_scenes(const Reader& r, const json& root, GltfDocument& d) {
    const json& nodes = top_array(r, root, "nodes");
    for (size_t i = 0; i < nodes.size(); ++i) {
        const std::string f = Reader::at("nodes", i);
        const json& j = nodes[i];
        GltfNode n;
        n.name = r.name(j, f);
        if (const json* v = Reader::find(j, "mesh"))
            n.mesh = int(r.index(*v, Reader::at(f, "mesh"), d.meshes.size(), "meshes"));
        if (const json* v = Reader::find(j, "camera"))
            n.camera = int(r.index(*v, Reader::at(f, "camera"), d.cameras.size(), "cameras"));
        if (const json* v = Reader::find(j, "skin")) {
            r.integer(*v, Reader::at(f, "skin"), 0, 1u << 30);
            n.skin = true;
        }
        if (const json* c = Reader::find(j, "children"))
            for (size_t k = 0; k < r.array(*c, Reader::at(f, "children")).size(); ++k)
                n.children.push_back(r.index((*c)[k], Reader::at(Reader::at(f, "children"), k),
                                             nodes.size(), "nodes"));
        if (const json* x = r.extension(j, f, "KHR_lights_punctual")) {
            const std::string xf = Reader::at(Reader::at(f, "extensions"), "KHR_lights_punctual");
            n.light = int(r.index(r.required(*x, xf, "light"), Reader::at(xf, "light"),
                                  d.lights.size(), "extensions.KHR_lights_punctual.lights"));
        }
        n.local = read_node_transform(r, j, f);
        d.nodes.push_back(std::move(n));
    }
    // The hierarchy is a forest (spec 3.5.3): no node is the child of two parents, so none is
    // its own ancestor either unless the parents form a cycle, which the root walk finds.
    std::vector<int> parent(d.nodes.size(), GLTF_NONE);
    for (size_t i = 0; i < d.nodes.size(); ++i)
        for (size_t k = 0; k < d.nodes[i].children.size(); ++k) {
            const uint32_t c = d.nodes[i].children[k];
            if (parent[c] != GLTF_NONE || c == i)
                r.fail(Reader::at(Reader::at(Reader::at("nodes", i), "children"), k),
                       c == i
                           ? fmt::format("node {} is its own child", c)
                           : fmt::format("node {} is already a child of nodes[{}]", c, parent[c]));
            parent[c] = int(i);
        }
    for (size_t i = 0; i < d.nodes.size(); ++i) {
        // Walking up from every node must end at a root within as many steps as there are nodes.
        size_t n = i, steps = 0;
        while (parent[n] != GLTF_NONE && steps++ <= d.nodes.size()) n = size_t(parent[n]);
        if (parent[n] != GLTF_NONE)
            r.fail(Reader::at("nodes", i), "is part of a cycle of children");
    }
    const json& scenes = top_array(r, root, "scenes");
    for (size_t i = 0; i < scenes.size(); ++i) {
        const std::string f = Reader::at("scenes", i);
        std::vector<uint32_t> roots;
        if (const json* ns = Reader::find(scenes[i], "nodes"))
            for (size_t k = 0; k < r.array(*ns, Reader::at(f, "nodes")).size(); ++k) {
                const std::string nf = Reader::at(Reader::at(f, "nodes"), k);
                const uint32_t n = r.index((*ns)[k], nf, d.nodes.size(), "nodes");
                if (parent[n] != GLTF_NONE)
                    r.fail(nf, fmt::format("node {} is a child of nodes[{}], not a root", n,
                                           parent[n]));
                if (std::find(roots.begin(), roots.end(), n) != roots.end())
                    r.fail(nf, fmt::format("node {} is listed twice", n));
                roots.push_back(n);
            }
        d.scenes.push_back(std::move(roots));
    }
    if (const json* s = Reader::find(root, "scene"))
        d.scene = int(r.index(*s, "scene", d.scenes.size(), "scenes"));
}

} // namespace

const std::vector<std::string>& gltf_supported_extensions() {
    static const std::vector<std::string> list = {
        "KHR_lights_punctual",        "KHR_materials_emissive_strength",
        "KHR_materials_ior",          "KHR_materials_specular",
        "KHR_materials_transmission", "KHR_materials_volume",
        "KHR_mesh_quantization",      "KHR_texture_transform"};
    return list;
}

uint32_t gltf_component_size(uint32_t component_type) {
    switch (component_type) {
    case GLTF_BYTE:
    case GLTF_UNSIGNED_BYTE:
        return 1;
    case GLTF_SHORT:
    case GLTF_UNSIGNED_SHORT:
        return 2;
    case GLTF_UNSIGNED_INT:
    case GLTF_FLOAT:
        return 4;
    default:
        return 0;
    }
}

GltfDocument read_gltf_document(const std::string& path, const nlohmann::json& root, bool is_glb) {
    const Reader r(path);
    r.object(root, "the top level");
    GltfDocument d;
    d.path = path;
    read_asset(r, root);
    read_extensions(r, root, d);
    read_buffers(r, root, is_glb, d);
    read_accessors(r, root, d);
    read_images_and_textures(r, root, d);
    // Materials name textures; meshes name materials; nodes name meshes, cameras and lights.
    const json& materials = top_array(r, root, "materials");
    for (size_t i = 0; i < materials.size(); ++i)
        d.materials.push_back(
            read_material(r, materials[i], Reader::at("materials", i), d.textures.size()));
    read_meshes(r, root, d);
    read_cameras_and_lights(r, root, d);
    read_nodes_and_scenes(r, root, d);
    if (const json* a = Reader::find(root, "animations"))
        d.animations = r.array(*a, "animations").size();
    if (const json* s = Reader::find(root, "skins")) d.skins = r.array(*s, "skins").size();
    return d;
}

} // namespace tp
