// Writes a whole text file through a temporary name and a rename, like the image writers, so
// that a failure never leaves a partial file. Throws RuntimeError naming the file.
#pragma once

#include <string>

namespace tp {

void write_text_file(const std::string& path, const std::string& text);

} // namespace tp
