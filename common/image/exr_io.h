// OpenEXR files, through the OpenEXR library (present in every build, the GPU bundle too).
// Renders are written as docs/design.md says: float32 R, G, B = per-pixel mean, variance.R/G/B =
// variance of that mean, optional AOV layers, and twinpath:* header attributes.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tp {

struct ExrImage {
    int width = 0;
    int height = 0;
    std::map<std::string, std::vector<float>> channels; // row-major, top row first
    std::map<std::string, std::string> strings;         // string header attributes
    std::map<std::string, int64_t> integers;            // int header attributes
    std::map<std::string, double> reals;                // double header attributes

    bool has(const std::string& channel) const { return channels.count(channel) != 0; }
    const std::vector<float>& channel(const std::string& name) const;
};

// Writes through write_output_file (util/output_file.h): no partial image is left behind, a
// device is written in place. Throws RuntimeError naming the file and the reason on failure.
void write_exr(const std::string& path, const ExrImage& image);

// Reads every channel as float32. Throws InputError naming the file when it is missing or
// not a valid OpenEXR file.
ExrImage read_exr(const std::string& path);

} // namespace tp
