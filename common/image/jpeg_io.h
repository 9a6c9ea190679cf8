// JPEG through libjpeg-turbo (every build, the GPU bundle too): textures read into the texel
// words (image/texture.h).
#pragma once

#include "image/texture.h"

#include <string>
#include <string_view>

namespace tp {

// A baseline or progressive JPEG image (greyscale, YCbCr or RGB) as a TEXEL_RGBA8 texture of
// its 8-bit values, decoded straight into its texel words: grey repeats into R, G and B, alpha
// is opaque. No sRGB conversion: a texture slot decides how the values are read
// (shared/texture.h). `what` names the image in errors (a file, a glTF field). Throws
// InputError for data that is not a JPEG image libjpeg decodes (a truncated file among them:
// libjpeg would fill the missing rows with grey and only warn), and for CMYK images.
Texture decode_jpeg(std::string_view bytes, const std::string& what);
// The same from a file, read as it decodes (the file is not held in memory).
Texture read_jpeg(const std::string& path);

} // namespace tp
