// Writes a whole text file through write_output_file (util/output_file.h), like the image
// writers: no partial file, a device written in place. Throws RuntimeError naming the file.
#pragma once

#include <string>

namespace tp {

void write_text_file(const std::string& path, const std::string& text);

} // namespace tp
