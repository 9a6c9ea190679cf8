#include "scene/scene_hash.h"

#include <fmt/core.h>

namespace tp {

void add_scene_content(Fnv1a& h, const FlatScene& s) {
    h.array(s.materials);
    h.array(s.meshes);
    h.array(s.positions);
    h.array(s.normals);
    h.array(s.uvs);
    h.array(s.uvs1);
    h.array(s.tangents);
    h.array(s.triangles);
    h.array(s.instances);
    h.array(s.lights);
    h.array(s.light_table);
    h.array(s.textures);
    // The images' texel words as one array (its length, then every image's words in order).
    size_t words = 0;
    for (const Texture& t : s.images) words += t.words.size();
    h.value(uint64_t(words));
    for (const Texture& t : s.images) h.bytes(t.words.data(), t.words.size() * sizeof(uint32_t));
    h.array(s.texture_slots);
    h.array(s.env_table);
    const RenderParams& p = s.params;
    h.value(p.light_count);
    h.value(p.env_light);
    h.value(p.env_texture);
    h.value(p.env_alias_offset);
    h.value(p.env_rotation);
}

std::string scene_hash(const FlatScene& scene) {
    Fnv1a h;
    add_scene_content(h, scene);
    return fmt::format("{:016x}", h.get());
}

uint64_t render_inputs_hash(const FlatScene& s) {
    Fnv1a h;
    h.value(s.params);
    h.value(s.spp);
    add_scene_content(h, s);
    return h.get();
}

} // namespace tp
