#include "util/json_file.h"

#include "util/output_file.h"

#include <nlohmann/json.hpp>

namespace tp {

void write_json(const std::string& path, const nlohmann::json& j) {
    write_output_file(path, j.dump(2) + "\n");
}

} // namespace tp
