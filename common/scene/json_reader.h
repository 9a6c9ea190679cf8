// Reading a JSON scene description field by field: every accessor checks the type and range of
// one value and, on failure, throws InputError naming the file and the field path
// (`materials.white.Kd[1]`, `nodes[3].matrix[5]`). Shared by the native JSON scene format
// (json_loader.h) and glTF (gltf_document.h).
#pragma once

#include "shared/lang.h"

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string>

namespace tp {

// Parses JSON text read from `path`; a syntax error, a number beyond double's range or a
// repeated key (json_duplicate_keys.h) is an InputError with the line and column.
nlohmann::json parse_json_text(const std::string& path, const std::string& text);

// parse_json_text of the whole file at `path`.
nlohmann::json parse_json_file(const std::string& path);

class JsonReader {
  public:
    using json = nlohmann::json;

    explicit JsonReader(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& field, const std::string& what) const;

    // Unknown keys are errors: a misspelt key must not be silently ignored.
    void keys(const json& j, const std::string& field,
              std::initializer_list<const char*> allowed) const;

    static std::string join(const std::string& a, const std::string& b) {
        return a.empty() ? b : a + "." + b;
    }

    float number(const json& j, const std::string& field) const {
        return float(coordinate(j, field));
    }
    float number(const json& j, const std::string& field, float lo, float hi) const;

    // A number within float's range, kept in double (positions: scene/scene.h).
    double coordinate(const json& j, const std::string& field) const;

    // An integer in [lo, hi].
    uint32_t count(const json& j, const std::string& field, uint32_t lo, uint32_t hi) const;

    vec3 vector3(const json& j, const std::string& field) const;
    glm::dvec3 position(const json& j, const std::string& field) const;
    vec3 color(const json& j, const std::string& field) const; // non-negative
    std::string string(const json& j, const std::string& field) const;
    bool boolean(const json& j, const std::string& field) const;
    const json& required(const json& j, const std::string& field, const char* key) const;

    // A file named by a string field, relative to the JSON file's directory; it must exist.
    std::filesystem::path file_path(const json& j, const std::string& field) const;

    const std::string& file() const { return file_; }

  private:
    std::string file_;
};

} // namespace tp
