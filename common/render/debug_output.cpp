#include "render/debug_output.h"

#include "util/error.h"
#include "util/output_file.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

namespace tp {
namespace {

using nlohmann::json;

// JSON has no NaN or infinity: they are written as the strings "nan", "inf", "-inf".
json number(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return v;
}
json number(float v) {
    return number(double(v));
}
json vec(vec3 v) {
    return json::array({number(v.x), number(v.y), number(v.z)});
}
json index(uint32_t i) {
    return i == NO_INDEX ? json(-1) : json(i);
}

const char* event_name(uint32_t e) {
    return e == VERTEX_HIT ? "hit" : "miss";
}

const char* termination_name(uint32_t t) {
    switch (t) {
    case TERM_CONTINUE:
        return "continue";
    case TERM_ESCAPED:
        return "escaped";
    case TERM_MAX_DEPTH:
        return "max_depth";
    case TERM_NO_SCATTER:
        return "no_scatter";
    case TERM_INCONSISTENT:
        return "inconsistent";
    case TERM_ROULETTE:
        return "roulette";
    default:
        return "unknown";
    }
}

const char* shadow_name(uint32_t s) {
    return s == SHADOW_UNOCCLUDED ? "unoccluded" : s == SHADOW_OCCLUDED ? "occluded" : "none";
}

std::string lobe_name(uint32_t lobe) {
    if (lobe == LOBE_NONE) return "none";
    std::string s;
    const std::pair<uint32_t, const char*> names[] = {{LOBE_DIFFUSE, "diffuse"},
                                                      {LOBE_GLOSSY, "glossy"},
                                                      {LOBE_SPECULAR, "specular"},
                                                      {LOBE_TRANSMISSION, "transmission"}};
    for (const auto& [bit, name] : names)
        if (lobe & bit) s += (s.empty() ? "" : "|") + std::string(name);
    return s;
}

// The names of PathVertex::rng's slots (RNG_* of rng.h).
const char* const kRngNames[PATH_LOG_RNG] = {
    "rng.light_slot", "rng.light_coin", "rng.light_u", "rng.light_v", "rng.env_slot",
    "rng.env_coin",   "rng.lobe",       "rng.dir_u",   "rng.dir_v",   "rng.roulette"};

json vertex_json(const PathVertex& v) {
    json j;
    j["sample"] = v.sample_index;
    j["bounce"] = v.bounce;
    j["event"] = event_name(v.event);
    j["ray_origin"] = vec(v.ray_origin);
    j["ray_dir"] = vec(v.ray_dir);
    j["t"] = number(v.t);
    j["instance"] = index(v.instance);
    j["primitive"] = index(v.primitive);
    j["bary"] = json::array({number(v.bary.x), number(v.bary.y)});
    j["position"] = vec(v.position);
    j["ng"] = vec(v.ng);
    j["ns"] = vec(v.ns);
    j["material"] = index(v.material);
    j["base_color"] = vec(v.base_color);
    j["roughness"] = number(v.roughness);
    j["metallic"] = number(v.metallic);
    j["transmission"] = number(v.transmission);
    j["alpha"] = number(v.alpha);
    j["cos_emit"] = number(v.cos_emit);
    j["emitted"] = vec(v.emitted);
    j["mis_emission"] = number(v.mis_emission);
    j["light"] = index(v.light);
    for (uint32_t k = 0; k < PATH_LOG_RNG; ++k) j[kRngNames[k]] = number(v.rng[k]);
    j["light_wi"] = vec(v.light_wi);
    j["light_pdf"] = number(v.light_pdf);
    j["light_f"] = vec(v.light_f);
    j["light_bsdf_pdf"] = number(v.light_bsdf_pdf);
    j["mis_light"] = number(v.mis_light);
    j["nee"] = vec(v.nee);
    j["shadow"] = shadow_name(v.shadow);
    j["lobe"] = lobe_name(v.lobe);
    j["wi"] = vec(v.wi);
    j["bsdf_pdf"] = number(v.bsdf_pdf);
    j["bsdf_weight"] = vec(v.bsdf_weight);
    j["roulette_q"] = number(v.roulette_q);
    j["throughput"] = vec(v.throughput);
    j["radiance"] = vec(v.radiance);
    j["termination"] = termination_name(v.termination);
    return j;
}

} // namespace

const std::vector<PathLogField>& path_log_fields() {
    using K = FieldKind;
    static const std::vector<PathLogField> fields = {
        {"event", K::Exact},
        {"ray_origin", K::Geometry},
        {"ray_dir", K::Direction},
        {"t", K::Geometry},
        {"instance", K::Exact},
        {"primitive", K::Exact},
        {"bary", K::Direction},
        {"position", K::Geometry},
        {"ng", K::Direction},
        {"ns", K::Direction},
        {"material", K::Exact},
        {"base_color", K::Radiometric},
        {"roughness", K::Radiometric},
        {"metallic", K::Radiometric},
        {"transmission", K::Radiometric},
        {"alpha", K::Radiometric},
        {"cos_emit", K::Direction},
        {"emitted", K::Radiometric},
        {"mis_emission", K::Radiometric},
        {"rng.light_slot", K::Exact},
        {"rng.light_coin", K::Exact},
        {"light", K::Exact},
        {"rng.light_u", K::Exact},
        {"rng.light_v", K::Exact},
        {"rng.env_slot", K::Exact},
        {"rng.env_coin", K::Exact},
        {"light_wi", K::Direction},
        {"light_pdf", K::Radiometric},
        {"light_f", K::Radiometric},
        {"light_bsdf_pdf", K::Radiometric},
        {"mis_light", K::Radiometric},
        {"shadow", K::Exact},
        {"nee", K::Radiometric},
        {"rng.lobe", K::Exact},
        {"rng.dir_u", K::Exact},
        {"rng.dir_v", K::Exact},
        {"lobe", K::Exact},
        {"wi", K::Direction},
        {"bsdf_pdf", K::Radiometric},
        {"bsdf_weight", K::Radiometric},
        {"rng.roulette", K::Exact},
        {"roulette_q", K::Radiometric},
        {"throughput", K::Radiometric},
        {"radiance", K::Radiometric},
        {"termination", K::Exact},
    };
    return fields;
}

const char* field_kind_name(FieldKind k) {
    switch (k) {
    case FieldKind::Exact:
        return "exact";
    case FieldKind::Geometry:
        return "geometry";
    case FieldKind::Direction:
        return "direction";
    case FieldKind::Radiometric:
        return "radiometric";
    }
    return "?";
}

uint32_t integrator_from_name(const std::string& name) {
    for (uint32_t i = INTEGRATOR_PATH; i <= INTEGRATOR_COST; ++i)
        if (name == integrator_name(i)) return i;
    input_error("--integrator {}: expected path, normals, albedo, depth or cost", name);
}

const char* integrator_name(uint32_t integrator) {
    switch (integrator) {
    case INTEGRATOR_PATH:
        return "path";
    case INTEGRATOR_NORMALS:
        return "normals";
    case INTEGRATOR_ALBEDO:
        return "albedo";
    case INTEGRATOR_DEPTH:
        return "depth";
    case INTEGRATOR_COST:
        return "cost";
    default:
        return "?";
    }
}

json path_log_json(const PathLogInfo& info, const std::vector<PathVertex>& records) {
    json j;
    j["format"] = "twinpath path log";
    j["version"] = 2; // 2: positions relative to "origin"
    j["backend"] = info.backend;
    j["mode"] = info.mode;
    j["device"] = info.device;
    j["scene"] = info.scene;
    j["seed"] = info.seed;
    j["sampler"] = info.sampler;
    j["width"] = info.width;
    j["height"] = info.height;
    j["spp"] = info.spp;
    j["max_depth"] = info.max_depth;
    j["min_depth"] = info.min_depth;
    j["pixel"] = {info.pixel_x, info.pixel_y};
    j["origin"] = {info.origin.x, info.origin.y, info.origin.z};
    j["dropped_records"] = info.dropped;
    json paths = json::array();
    for (size_t i = 0; i < records.size();) {
        const uint32_t s = records[i].sample_index;
        json vertices = json::array();
        vec3 L(0.0f);
        for (; i < records.size() && records[i].sample_index == s; ++i) {
            vertices.push_back(vertex_json(records[i]));
            L = records[i].radiance;
        }
        paths.push_back({{"sample", s}, {"radiance", vec(L)}, {"vertices", std::move(vertices)}});
    }
    j["paths"] = std::move(paths);
    return j;
}

void write_path_log(const std::string& path, const PathLogInfo& info,
                    const std::vector<PathVertex>& records) {
    write_output_file(path, path_log_json(info, records).dump(1) + "\n");
}

void add_aov_layers(ExrImage& img, const std::vector<PixelAov>& aovs) {
    const size_t n = aovs.size();
    const char* albedo[3] = {"albedo.R", "albedo.G", "albedo.B"};
    const char* normal[3] = {"normal.X", "normal.Y", "normal.Z"};
    for (int c = 0; c < 3; ++c) {
        img.channels[albedo[c]].resize(n);
        img.channels[normal[c]].resize(n);
    }
    std::vector<float>& depth = img.channels["depth.Z"];
    std::vector<float>& inst = img.channels["id.instance"];
    std::vector<float>& mat = img.channels["id.material"];
    // glTF's metallic and roughness with their textures applied (0 for other materials).
    std::vector<float>& roughness = img.channels["pbr.roughness"];
    std::vector<float>& metallic = img.channels["pbr.metallic"];
    depth.resize(n);
    inst.resize(n);
    mat.resize(n);
    roughness.resize(n);
    metallic.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const PixelAov& a = aovs[i];
        const bool miss = a.instance == NO_INDEX;
        for (int c = 0; c < 3; ++c) {
            img.channels[albedo[c]][i] = a.albedo[c];
            img.channels[normal[c]][i] = a.normal[c];
        }
        depth[i] = miss ? std::numeric_limits<float>::infinity() : a.depth;
        inst[i] = miss ? -1.0f : float(a.instance);
        mat[i] = miss ? -1.0f : float(a.material);
        roughness[i] = a.roughness;
        metallic[i] = a.metallic;
    }
}

} // namespace tp
