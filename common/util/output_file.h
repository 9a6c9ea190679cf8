// Every file a command writes (images, statistics, logs, reports) goes through here, so that
// all of them fail the same way: a write, flush or close that fails throws RuntimeError naming
// the file and the system's reason (exit 3), and leaves no partial file behind.
#pragma once

#include <string>
#include <string_view>

namespace tp {

// Writes `bytes` to `path`. A regular file (or a new one) is written as PATH.partial and renamed
// over PATH, so PATH is either its old self or the whole new file. Anything else that exists
// there (a device such as /dev/null or /dev/full, a FIFO) is written in place: a rename would
// replace the device node with a regular file.
void write_output_file(const std::string& path, std::string_view bytes);

} // namespace tp
