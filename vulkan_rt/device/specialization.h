// The specialization constants of the render shaders, bound to a stage at pipeline creation:
// the scene's feature mask (SPEC_SCENE_FEATURES, shaders/features.glsl), how the invocations
// take work items (SPEC_ITEM_SCHEDULE, shaders/render_items.glsl) and how many images the scene
// binds (SPEC_IMAGE_COUNT, shaders/scene_access.glsl). A shader without them ignores them
// (Vulkan allows unused map entries).
#pragma once

#include "shaders/interface.h"
#include "shared/features.h"

#include <cstddef>
#include <vulkan/vulkan.h>

namespace tp {

struct RenderConstants {
    uint32_t features = FEATURES_ALL;               // shared/features.h
    uint32_t item_schedule = ITEM_SCHEDULE_COUNTER; // ITEM_SCHEDULE_* (item_schedule.h)
    uint32_t image_count = IMAGE_SLOTS;             // the scene's images (scene_images.h)
};

struct RenderSpecialization {
    explicit RenderSpecialization(const RenderConstants& c) : constants(c) {
        entries[0] = {SPEC_SCENE_FEATURES, offsetof(RenderConstants, features), sizeof(uint32_t)};
        entries[1] = {SPEC_ITEM_SCHEDULE, offsetof(RenderConstants, item_schedule),
                      sizeof(uint32_t)};
        entries[2] = {SPEC_IMAGE_COUNT, offsetof(RenderConstants, image_count), sizeof(uint32_t)};
        info.mapEntryCount = 3;
        info.pMapEntries = entries;
        info.dataSize = sizeof(RenderConstants);
        info.pData = &constants;
    }
    RenderSpecialization(const RenderSpecialization&) = delete;
    RenderSpecialization& operator=(const RenderSpecialization&) = delete;

    RenderConstants constants;
    VkSpecializationMapEntry entries[3]{};
    VkSpecializationInfo info{};
};

} // namespace tp
