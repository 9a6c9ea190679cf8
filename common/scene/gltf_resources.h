// The binary data of a glTF asset: its buffers (the GLB's BIN chunk, base64 data: URIs, or
// files next to the asset) and its images, decoded on request by the decoders of every other
// texture (image/texture_io.h: PNG through libpng, JPEG through libjpeg-turbo), straight into
// their texel words. The sizes and the file names are checked here, and errors name the field.
#pragma once

#include "image/texture.h"
#include "scene/gltf_document.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tp {

class GltfResources {
  public:
    // Reads every buffer of `doc` and checks that each has at least its byteLength; `bin` is
    // the GLB's BIN chunk (buffer 0 without a uri). Keeps a reference to `doc`, and `bin` must
    // outlive this object.
    GltfResources(const GltfDocument& doc, std::string_view bin, bool has_bin);

    // The bytes of buffer view `view` (inside its buffer: checked when the document was read).
    std::string_view view_bytes(uint32_t view) const;

    // Image `image` with its 8- or 16-bit values as stored (image/texture.h): whether they are
    // sRGB colour depends on the slot that reads them. An image in a well-known format that
    // twinpath does not decode (glTF's PNG and JPEG are what it decodes; BMP, GIF, WebP, KTX2 by
    // their bytes or mimeType) is nullopt, with `undecoded` naming the format. `used_by` names
    // the field that needs it, for the error (InputError) when the image is missing or its
    // data is not a valid image.
    std::optional<Texture> decode_image(uint32_t image, const std::string& used_by,
                                        std::string& undecoded) const;

  private:
    const GltfDocument& doc_;
    std::vector<std::string> owned_; // buffers read from files or data: URIs
    std::vector<std::string_view> buffers_;
};

// A uri's percent-encoded bytes decoded (RFC 3986, section 2.1: "%20" is a space).
std::string gltf_percent_decode(std::string_view uri);

// A data: URI's media type and bytes (RFC 2397, base64 only: glTF's embedded buffers and
// images), or nullopt when `uri` is not a base64 data: URI or its payload is not base64.
struct DataUri {
    std::string media_type;
    std::string bytes;
};
std::optional<DataUri> parse_data_uri(std::string_view uri);

} // namespace tp
