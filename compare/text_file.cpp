#include "compare/text_file.h"

#include "util/error.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace tp {

void write_text_file(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".partial";
    {
        std::ofstream f(tmp, std::ios::binary);
        f << text;
        if (!f.good()) {
            std::remove(tmp.c_str());
            runtime_error("cannot write {}", path);
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::remove(tmp.c_str());
        runtime_error("cannot write {}: {}", path, ec.message());
    }
}

} // namespace tp
