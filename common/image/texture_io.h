// Image textures and environment maps from files. With OpenImageIO (the default build) any
// format it reads; without it (the GPU bundle) OpenEXR only. 8- and 16-bit images keep their
// integer values (image/texture.h: a texture slot decides whether they are sRGB colour); float
// images are taken as linear.
#pragma once

#include "image/texture.h"

#include <string>

namespace tp {

// Throws InputError naming the file when it is missing, unreadable or unsupported.
Texture load_texture(const std::string& path);

} // namespace tp
