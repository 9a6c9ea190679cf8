#include "scene/json_reader.h"

#include "scene/json_duplicate_keys.h"
#include "scene/json_sax.h"
#include "scene/text_parse.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;

namespace tp {
namespace {

// Where the first error in a JSON text is: its byte offset, from nlohmann's SAX interface, and
// the field path of the value being read there (`nodes[0].matrix[5]`), so that a malformed
// value such as Python's NaN is reported at its field.
struct ErrorLocation : JsonSaxAcceptAll {
    struct Frame {
        bool array;
        std::string key; // objects: the key whose value is being read
        long index = -1; // arrays: the last element started
    };
    std::vector<Frame> open;
    size_t offset = 0;
    std::string field;

    void value() {
        if (!open.empty() && open.back().array) ++open.back().index;
    }
    bool null() override { return value(), true; }
    bool boolean(bool) override { return value(), true; }
    bool number_integer(number_integer_t) override { return value(), true; }
    bool number_unsigned(number_unsigned_t) override { return value(), true; }
    bool number_float(number_float_t, const string_t&) override { return value(), true; }
    bool string(string_t&) override { return value(), true; }
    bool start_object(std::size_t) override {
        value();
        open.push_back({false, "", -1});
        return true;
    }
    bool key(string_t& k) override {
        open.back().key = clip(k);
        return true;
    }
    bool end_object() override { return open.pop_back(), true; }
    bool start_array(std::size_t) override {
        value();
        open.push_back({true, "", -1});
        return true;
    }
    bool end_array() override { return open.pop_back(), true; }
    bool parse_error(std::size_t position, const std::string&,
                     const nlohmann::detail::exception&) override {
        offset = position;
        for (size_t i = 0; i < open.size(); ++i) {
            const Frame& f = open[i];
            // In the innermost array the failing element is the one after the last started.
            if (f.array)
                field += fmt::format("[{}]", f.index + (i + 1 == open.size() ? 1 : 0));
            else if (!f.key.empty())
                field += (field.empty() ? "" : ".") + f.key;
        }
        return false;
    }
};

std::string located(const std::string& field) {
    return field.empty() ? "" : " in " + field;
}

} // namespace

json parse_json_text(const std::string& path, const std::string& text) {
    try {
        json root = json::parse(text);
        reject_duplicate_keys(path, text);
        return root;
    } catch (const json::parse_error& e) {
        ErrorLocation where;
        json::sax_parse(text, &where);
        // nlohmann's message carries "at line L, column C".
        input_error("{}: malformed JSON{}: {}", path, located(where.field), e.what());
    } catch (const json::out_of_range& e) {
        // A number beyond double's range (1e999) is reported without a position.
        ErrorLocation where;
        json::sax_parse(text, &where);
        const size_t end = std::min(where.offset, text.size());
        const size_t line = 1 + size_t(std::count(text.begin(), text.begin() + long(end), '\n'));
        const size_t line_start = text.rfind('\n', end == 0 ? 0 : end - 1);
        const size_t column = line_start == std::string::npos ? end : end - line_start - 1;
        input_error("{}: malformed JSON at line {}, column {}{}: {}", path, line, column,
                    located(where.field), e.what());
    }
}

json parse_json_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) input_error("{}: cannot open file", path);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    return parse_json_text(path, text);
}

void JsonReader::fail(const std::string& field, const std::string& what) const {
    throw InputError(fmt::format("{}: {}: {}", file_, field, what));
}

void JsonReader::keys(const json& j, const std::string& field,
                      std::initializer_list<const char*> allowed) const {
    if (!j.is_object()) fail(field, "expected an object");
    std::set<std::string> ok(allowed.begin(), allowed.end());
    for (const auto& item : j.items())
        if (!ok.count(item.key())) {
            std::string list;
            for (const char* a : allowed) list += fmt::format("{}{}", list.empty() ? "" : ", ", a);
            fail(join(field, item.key()), fmt::format("unknown key (expected one of: {})", list));
        }
}

double JsonReader::coordinate(const json& j, const std::string& field) const {
    if (!j.is_number()) fail(field, "expected a number");
    const double v = j.get<double>();
    if (!std::isfinite(v) || std::abs(v) > 3.4e38) fail(field, "must be a finite float");
    return v;
}

float JsonReader::number(const json& j, const std::string& field, float lo, float hi) const {
    const float v = number(j, field);
    if (v < lo || v > hi) fail(field, fmt::format("must lie in [{}, {}], got {}", lo, hi, v));
    return v;
}

uint32_t JsonReader::count(const json& j, const std::string& field, uint32_t lo,
                           uint32_t hi) const {
    if (!j.is_number_integer()) fail(field, "expected an integer");
    // Unsigned values above 2^63 would wrap to negative as long long.
    const bool in_range = j.is_number_unsigned()
                              ? j.get<uint64_t>() >= lo && j.get<uint64_t>() <= hi
                              : j.get<int64_t>() >= lo && j.get<int64_t>() <= hi;
    if (!in_range) fail(field, fmt::format("must lie in [{}, {}], got {}", lo, hi, j.dump()));
    return uint32_t(j.get<uint64_t>());
}

vec3 JsonReader::vector3(const json& j, const std::string& field) const {
    if (!j.is_array() || j.size() != 3) fail(field, "expected an array of 3 numbers");
    return vec3(number(j[0], field + "[0]"), number(j[1], field + "[1]"),
                number(j[2], field + "[2]"));
}

glm::dvec3 JsonReader::position(const json& j, const std::string& field) const {
    if (!j.is_array() || j.size() != 3) fail(field, "expected an array of 3 numbers");
    return glm::dvec3(coordinate(j[0], field + "[0]"), coordinate(j[1], field + "[1]"),
                      coordinate(j[2], field + "[2]"));
}

vec3 JsonReader::color(const json& j, const std::string& field) const {
    const vec3 c = vector3(j, field);
    if (c.x < 0 || c.y < 0 || c.z < 0) fail(field, "colors must not be negative");
    return c;
}

std::string JsonReader::string(const json& j, const std::string& field) const {
    if (!j.is_string()) fail(field, "expected a string");
    return j.get<std::string>();
}

bool JsonReader::boolean(const json& j, const std::string& field) const {
    if (!j.is_boolean()) fail(field, "expected true or false");
    return j.get<bool>();
}

const json& JsonReader::required(const json& j, const std::string& field, const char* key) const {
    if (!j.contains(key)) fail(join(field, key), "is required");
    return j[key];
}

fs::path JsonReader::file_path(const json& j, const std::string& field) const {
    fs::path p = string(j, field);
    if (p.is_relative()) p = fs::path(file_).parent_path() / p;
    if (!fs::exists(p)) fail(field, fmt::format("file '{}' does not exist", p.string()));
    return p;
}

} // namespace tp
