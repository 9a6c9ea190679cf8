#include "compare/text_file.h"

#include "util/output_file.h"

namespace tp {

void write_text_file(const std::string& path, const std::string& text) {
    write_output_file(path, text);
}

} // namespace tp
