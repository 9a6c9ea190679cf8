// Image textures and environment maps from files, and the image formats twinpath tells apart
// by their first bytes. Every build decodes PNG (libpng), JPEG (libjpeg-turbo) and OpenEXR
// (OpenEXR) itself, the GPU bundle too; the default build reads any other format OpenImageIO
// reads. 8- and 16-bit images keep their integer values (image/texture.h: a texture slot
// decides whether they are sRGB colour); float images are taken as linear.
#pragma once

#include "image/texture.h"

#include <string>
#include <string_view>

namespace tp {

enum class ImageFormat { png, jpeg, exr, other };

// The format of an image from its first bytes (at least 8 for a certain answer): the PNG
// signature \x89PNG\r\n\x1a\n, JPEG's start-of-image marker FF D8 FF, OpenEXR's magic number
// 76 2F 31 01.
ImageFormat image_format_of(std::string_view head);

// The name of a well-known image format twinpath does not decode (BMP, GIF, WebP, KTX2, DDS,
// TIFF, Radiance HDR, Basis) from its first bytes (at least 12), or empty.
std::string undecoded_format_name(std::string_view head);

// Throws InputError naming the file when it is missing, unreadable or unsupported. The
// texture's `source` is the path.
Texture load_texture(const std::string& path);

} // namespace tp
