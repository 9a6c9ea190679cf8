#include "scene/texture_slots.h"

#include <cstring>

namespace tp {

int add_texture_slot(Scene& scene, const TextureSlot& slot) {
    // Byte equality: a slot is plain data without padding (shared/types.h), and slots built
    // from the same numbers hold the same bits.
    for (size_t i = 0; i < scene.texture_slots.size(); ++i)
        if (std::memcmp(&scene.texture_slots[i], &slot, sizeof slot) == 0) return int(i);
    scene.texture_slots.push_back(slot);
    return int(scene.texture_slots.size() - 1);
}

} // namespace tp
