#include "compare/pathdiff.h"

#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>

namespace tp {
namespace {

using nlohmann::json;

double as_number(const json& v) {
    if (v.is_number()) return v.get<double>();
    if (v.is_string()) {
        const std::string s = v.get<std::string>();
        if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
        if (s == "inf") return std::numeric_limits<double>::infinity();
        if (s == "-inf") return -std::numeric_limits<double>::infinity();
    }
    return std::numeric_limits<double>::quiet_NaN();
}

bool is_numeric(const json& v) {
    if (v.is_number()) return true;
    if (v.is_string()) return v == "nan" || v == "inf" || v == "-inf";
    return v.is_array() &&
           std::all_of(v.begin(), v.end(), [](const json& x) { return is_numeric(x); });
}

// One component: NaN equals NaN, infinities equal themselves; `excess` is how far beyond the
// tolerance the difference is (<= 0: within).
bool component_equal(double a, double b, FieldKind kind, const PathDiffTolerances& tol,
                     double& allowed) {
    allowed = 0;
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
    if (std::isinf(a) || std::isinf(b)) return a == b;
    const double d = std::fabs(a - b), m = std::max(std::fabs(a), std::fabs(b));
    switch (kind) {
    case FieldKind::Exact:
        allowed = 0;
        break;
    case FieldKind::Geometry:
        allowed = tol.geometry * std::max(1.0, m);
        break;
    case FieldKind::Direction:
        allowed = tol.direction;
        break;
    case FieldKind::Radiometric:
        allowed = tol.radiometric * m + 1e-6;
        break;
    }
    return d <= allowed;
}

// Whether field values a and b agree; `why` explains a disagreement.
bool field_equal(const json& a, const json& b, FieldKind kind, const PathDiffTolerances& tol,
                 std::string& why) {
    if (a.is_null() || b.is_null()) {
        why = a.is_null() && b.is_null() ? "" : "missing in one log";
        return a.is_null() && b.is_null();
    }
    if (!is_numeric(a) || !is_numeric(b)) {
        why = "values differ";
        return a == b;
    }
    const json aa = a.is_array() ? a : json::array({a});
    const json bb = b.is_array() ? b : json::array({b});
    if (aa.size() != bb.size()) {
        why = "different number of components";
        return false;
    }
    for (size_t i = 0; i < aa.size(); ++i) {
        double allowed = 0;
        const double x = as_number(aa[i]), y = as_number(bb[i]);
        if (!component_equal(x, y, kind, tol, allowed)) {
            why = fmt::format("component {}: |{:.9g} - {:.9g}| = {:.3g} > {:.3g} ({} tolerance)", i,
                              x, y, std::fabs(x - y), allowed, field_kind_name(kind));
            return false;
        }
    }
    return true;
}

std::string show(const json& v) {
    if (v.is_null()) return "-";
    if (v.is_array()) {
        std::string s = "[";
        for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + show(v[i]);
        return s + "]";
    }
    if (v.is_number_float()) return fmt::format("{:.7g}", v.get<double>());
    if (v.is_string()) return v.get<std::string>();
    return v.dump();
}

// Both vertices side by side, every field, the diverging ones marked.
std::string vertex_table(const json* va, const json* vb, const std::string& first,
                         const PathDiffTolerances& tol) {
    std::string out = fmt::format("  {:2} {:<15} {:<42} {}\n", "", "field", "A", "B");
    for (const PathLogField& f : path_log_fields()) {
        const json a = va ? va->value(f.name, json()) : json();
        const json b = vb ? vb->value(f.name, json()) : json();
        std::string why;
        const bool eq = field_equal(a, b, f.kind, tol, why);
        const char* mark = f.name == first ? ">>" : eq ? "" : " *";
        out += fmt::format("  {:2} {:<15} {:<42} {}\n", mark, f.name, show(a), show(b));
    }
    return out;
}

void check_same(const std::string& name_a, const json& a, const std::string& name_b, const json& b,
                const char* key) {
    if (a.value(key, json()) != b.value(key, json()))
        input_error("{} and {} are logs of different renders: {} {} against {}", name_a, name_b,
                    key, show(a.value(key, json())), show(b.value(key, json())));
}

} // namespace

json read_path_log(const std::string& path) {
    std::ifstream in(path);
    if (!in) input_error("{}: cannot open the path log", path);
    json j;
    try {
        j = json::parse(in);
    } catch (const json::exception& e) {
        input_error("{}: not valid JSON ({})", path, e.what());
    }
    if (!j.is_object() || j.value("format", "") != "twinpath path log" || !j.contains("paths") ||
        !j["paths"].is_array())
        input_error("{}: not a twinpath path log (render --debug-log writes them)", path);
    for (const json& p : j["paths"])
        if (!p.is_object() || !p.contains("sample") || !p.contains("vertices") ||
            !p["vertices"].is_array())
            input_error("{}: a path without sample or vertices", path);
    return j;
}

PathDiffResult pathdiff(const std::string& name_a, const json& a, const std::string& name_b,
                        const json& b, const PathDiffTolerances& tol) {
    for (const char* key : {"pixel", "seed", "sampler", "width", "height"})
        check_same(name_a, a, name_b, b, key);
    PathDiffResult r;
    std::string header =
        fmt::format("A = {} ({} {}), B = {} ({} {}); pixel {}, seed {}\n", name_a,
                    a.value("backend", "?"), a.value("mode", ""), name_b, b.value("backend", "?"),
                    b.value("mode", ""), show(a["pixel"]), show(a["seed"]));
    // Paths are matched by sample index.
    std::map<uint32_t, const json*> paths_b;
    for (const json& p : b["paths"]) paths_b[p["sample"].get<uint32_t>()] = &p;
    size_t unmatched = 0;
    for (const json& pa : a["paths"]) {
        const uint32_t s = pa["sample"].get<uint32_t>();
        const auto it = paths_b.find(s);
        if (it == paths_b.end()) {
            ++unmatched;
            continue;
        }
        const json& va = pa["vertices"];
        const json& vb = (*it->second)["vertices"];
        ++r.paths_compared;
        const size_t n = std::min(va.size(), vb.size());
        for (size_t v = 0; v <= n && !r.diverged; ++v) {
            if (v == n) {
                if (va.size() == vb.size()) break;
                r.diverged = true;
                r.sample = s;
                r.vertex = n;
                r.field = "vertex count";
                r.value_a = std::to_string(va.size());
                r.value_b = std::to_string(vb.size());
                r.why = "every shared field agrees";
                r.report = fmt::format(
                    "{}paths diverge at sample {}: A has {} vertices, B has {} (every shared "
                    "field agrees)\nlast shared vertex {}:\n{}",
                    header, s, va.size(), vb.size(), n - 1,
                    vertex_table(&va[n - 1], &vb[n - 1], "", tol));
                break;
            }
            ++r.vertices_compared;
            for (const PathLogField& f : path_log_fields()) {
                std::string why;
                if (field_equal(va[v].value(f.name, json()), vb[v].value(f.name, json()), f.kind,
                                tol, why))
                    continue;
                r.diverged = true;
                r.sample = s;
                r.vertex = v;
                r.field = f.name;
                r.value_a = show(va[v].value(f.name, json()));
                r.value_b = show(vb[v].value(f.name, json()));
                r.why = why;
                std::string prev =
                    v == 0 ? "(the first vertex: the camera ray)\n"
                           : fmt::format("vertex {} before it agrees within tolerance\n", v - 1);
                r.report = fmt::format(
                    "{}paths diverge at sample {}, vertex {} (bounce {}), field {}: {}\n  A: {}\n  "
                    "B: {}\n{}vertex {} (>> first divergence, * other fields beyond "
                    "tolerance):\n{}",
                    header, s, v, show(va[v].value("bounce", json())), f.name, why,
                    show(va[v].value(f.name, json())), show(vb[v].value(f.name, json())), prev, v,
                    vertex_table(&va[v], &vb[v], f.name, tol));
                break;
            }
        }
        if (r.diverged) return r;
    }
    if (r.paths_compared == 0)
        input_error("{} and {} have no sample in common (render both with the same "
                    "--debug-sample)",
                    name_a, name_b);
    r.report = fmt::format("{}identical within tolerance: {} paths, {} vertices{}\n", header,
                           r.paths_compared, r.vertices_compared,
                           unmatched ? fmt::format(" ({} paths of A not in B)", unmatched) : "");
    return r;
}

} // namespace tp
