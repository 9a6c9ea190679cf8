#include "scene/gltf_textures.h"

#include "scene/text_parse.h"
#include "scene/texture_slots.h"

#include <fmt/format.h>

namespace tp {
namespace {

uint32_t wrap_bits(uint32_t gltf_wrap) {
    return gltf_wrap == GLTF_CLAMP_TO_EDGE     ? SLOT_WRAP_CLAMP
           : gltf_wrap == GLTF_MIRRORED_REPEAT ? SLOT_WRAP_MIRROR
                                               : SLOT_WRAP_REPEAT;
}

} // namespace

void gltf_slot_transform(const glm::dmat3& m, vec3& transform_s, vec3& transform_t) {
    // glm is column-major: m[column][row].
    transform_s = vec3(float(m[0][0]), float(m[1][0]), float(m[2][0]));
    transform_t = vec3(float(m[0][1]), float(m[1][1]), float(m[2][1]));
}

int GltfTextures::slot(const GltfTextureRef& ref, bool srgb, std::vector<std::string>& dropped,
                       std::vector<std::string>& ignored) {
    const GltfTexture& t = d_.textures[size_t(ref.texture)];
    if (t.source == GLTF_NONE) {
        std::string exts;
        for (const std::string& e : t.source_extensions)
            exts += (exts.empty() ? "" : ", ") + clip(e);
        dropped.push_back(fmt::format("{}: textures[{}] has no image twinpath decodes{}", ref.field,
                                      ref.texture,
                                      exts.empty() ? "" : " (its image is in " + exts + ")"));
        return NO_TEXTURE;
    }
    if (ref.tex_coord > 1) {
        dropped.push_back(fmt::format("{}: texCoord {}: twinpath reads TEXCOORD_0 and TEXCOORD_1",
                                      ref.field, ref.tex_coord));
        return NO_TEXTURE;
    }
    uint32_t sampling = (srgb ? SLOT_SRGB : 0u) | (ref.tex_coord == 1 ? SLOT_UV1 : 0u);
    if (t.sampler != GLTF_NONE) {
        const GltfSampler& sm = d_.samplers[size_t(t.sampler)];
        sampling |= wrap_bits(sm.wrap_s) | wrap_bits(sm.wrap_t) << SLOT_WRAP_T_SHIFT;
        if (sm.mag_filter == GLTF_NEAREST) sampling |= SLOT_NEAREST;
        if (sm.min_filter != 0)
            ignored.push_back(fmt::format(
                "{}: samplers[{}].minFilter {}: ignored (a path tracer has no ray footprint to "
                "pick a mip level; its many samples per pixel average the texture)",
                ref.field, t.sampler, sm.min_filter));
    }
    const uint32_t source = uint32_t(t.source);
    auto it = image_of_source_.find(source);
    if (it == image_of_source_.end()) {
        std::string format;
        std::optional<Texture> image = res_.decode_image(source, ref.field, format);
        const uint32_t index = image ? uint32_t(s_.textures.size()) : kUndecoded;
        if (image) s_.textures.push_back(std::move(*image));
        it = image_of_source_.emplace(source, index).first;
        undecoded_format_[source] = format;
    }
    if (it->second == kUndecoded) {
        dropped.push_back(fmt::format("{}: textures[{}]: images[{}] is {}: twinpath decodes PNG "
                                      "and JPEG images",
                                      ref.field, ref.texture, source,
                                      clip(undecoded_format_[source])));
        return NO_TEXTURE;
    }
    vec3 ts, tt;
    gltf_slot_transform(ref.transform, ts, tt);
    return add_texture_slot(s_, make_texture_slot(it->second, ts, tt, sampling));
}

} // namespace tp
