// The specialization constants of the render shaders, bound to a stage at pipeline creation:
// the scene's feature mask (SPEC_SCENE_FEATURES, shaders/features.glsl) and how the invocations
// take work items (SPEC_ITEM_SCHEDULE, shaders/render_items.glsl). A shader without them ignores
// them (Vulkan allows unused map entries).
#pragma once

#include "shaders/interface.h"
#include "shared/features.h"

#include <cstddef>
#include <vulkan/vulkan.h>

namespace tp {

struct RenderConstants {
    uint32_t features = FEATURES_ALL;               // shared/features.h
    uint32_t item_schedule = ITEM_SCHEDULE_COUNTER; // ITEM_SCHEDULE_* (item_schedule.h)
};

struct RenderSpecialization {
    explicit RenderSpecialization(const RenderConstants& c) : constants(c) {
        entries[0] = {SPEC_SCENE_FEATURES, offsetof(RenderConstants, features), sizeof(uint32_t)};
        entries[1] = {SPEC_ITEM_SCHEDULE, offsetof(RenderConstants, item_schedule),
                      sizeof(uint32_t)};
        info.mapEntryCount = 2;
        info.pMapEntries = entries;
        info.dataSize = sizeof(RenderConstants);
        info.pData = &constants;
    }
    RenderSpecialization(const RenderSpecialization&) = delete;
    RenderSpecialization& operator=(const RenderSpecialization&) = delete;

    RenderConstants constants;
    VkSpecializationMapEntry entries[2]{};
    VkSpecializationInfo info{};
};

} // namespace tp
