// PNG through libpng (every build, the GPU bundle too): textures read into the texel words
// (image/texture.h), 8-bit previews written, and the sRGB preview tone mapping used for `--png`
// and compare reports.
#pragma once

#include "image/texture.h"
#include "shared/tonemap.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tp {

// A PNG image (every colour type and bit depth) as a texture of its values as stored, decoded
// straight into its texel words: 8-bit and lower depths as TEXEL_RGBA8, 16-bit as TEXEL_RGBA16;
// grey repeats into R, G and B, a palette is looked up, a tRNS chunk becomes alpha, and an image
// without alpha is opaque. No gamma or sRGB conversion: a texture slot decides how the values
// are read (shared/texture.h). `what` names the image in errors (a file, a glTF field).
// Throws InputError for data that is not a valid PNG.
Texture decode_png(std::string_view bytes, const std::string& what);
// The same from a file, read as it decodes (the file is not held in memory).
Texture read_png(const std::string& path);

// rgb: width * height * 3 bytes, rows top to bottom. Written through write_output_file
// (util/output_file.h): no partial file, a device written in place. Throws RuntimeError.
void write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb);

// Linear radiance to display, pixel by pixel as the viewer's display pass (shared/tonemap.h,
// display_srgb8): non-finite values become magenta so they cannot hide.
std::vector<uint8_t> tonemap_srgb8(const std::vector<float>& r, const std::vector<float>& g,
                                   const std::vector<float>& b, float exposure_stops);

} // namespace tp
