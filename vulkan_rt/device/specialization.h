// The specialization constants of the render shaders (shaders/features.glsl): the scene's
// feature mask, bound to constant SPEC_SCENE_FEATURES of a stage at pipeline creation.
#pragma once

#include "shaders/interface.h"

#include <vulkan/vulkan.h>

namespace tp {

struct FeatureSpecialization {
    explicit FeatureSpecialization(uint32_t features) : mask(features) {
        entry.constantID = SPEC_SCENE_FEATURES;
        entry.offset = 0;
        entry.size = sizeof(uint32_t);
        info.mapEntryCount = 1;
        info.pMapEntries = &entry;
        info.dataSize = sizeof(uint32_t);
        info.pData = &mask;
    }
    FeatureSpecialization(const FeatureSpecialization&) = delete;
    FeatureSpecialization& operator=(const FeatureSpecialization&) = delete;

    uint32_t mask;
    VkSpecializationMapEntry entry{};
    VkSpecializationInfo info{};
};

} // namespace tp
