// The scene's texture-slot table (Scene::texture_slots) filled without repeats: materials that
// read the same image the same way share one slot, whichever loader made them.
#pragma once

#include "scene/scene.h"

namespace tp {

// The index of a slot equal to `slot` in scene.texture_slots, appended if there is none.
int add_texture_slot(Scene& scene, const TextureSlot& slot);

} // namespace tp
