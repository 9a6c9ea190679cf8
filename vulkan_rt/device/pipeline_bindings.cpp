#include "vulkan_rt/device/pipeline_bindings.h"

#include "util/error.h"
#include "vulkan_rt/device/vk_error.h"

#include <map>

namespace tp {

std::vector<BindingSlot> storage_slots(uint32_t count) {
    std::vector<BindingSlot> slots;
    for (uint32_t i = 0; i < count; ++i) slots.push_back({i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    return slots;
}

PipelineBindings::PipelineBindings(const VulkanContext& ctx, const std::vector<BindingSlot>& slots,
                                   VkShaderStageFlags stages, uint32_t push_bytes)
    : ctx_(ctx), stages_(stages), push_bytes_(push_bytes) {
    const VkDevice device = ctx.device();
    try {
        std::vector<VkDescriptorSetLayoutBinding> bindings;
        std::map<VkDescriptorType, uint32_t> counts;
        for (const BindingSlot& s : slots) {
            VkDescriptorSetLayoutBinding b{};
            b.binding = s.binding;
            b.descriptorType = s.type;
            b.descriptorCount = s.count;
            b.stageFlags = stages;
            bindings.push_back(b);
            counts[s.type] += s.count;
        }
        VkDescriptorSetLayoutCreateInfo sli{};
        sli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
        sli.bindingCount = uint32_t(bindings.size());
        sli.pBindings = bindings.data();
        vk_check(vkCreateDescriptorSetLayout(device, &sli, nullptr, &set_layout_),
                 "creating a descriptor set layout");

        VkPushConstantRange range{stages, 0, push_bytes};
        VkPipelineLayoutCreateInfo pli{};
        pli.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
        pli.setLayoutCount = 1;
        pli.pSetLayouts = &set_layout_;
        pli.pushConstantRangeCount = push_bytes > 0 ? 1 : 0;
        pli.pPushConstantRanges = &range;
        vk_check(vkCreatePipelineLayout(device, &pli, nullptr, &layout_),
                 "creating a pipeline layout");

        std::vector<VkDescriptorPoolSize> sizes;
        for (const auto& [type, count] : counts) sizes.push_back({type, count});
        VkDescriptorPoolCreateInfo dpi{};
        dpi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
        dpi.maxSets = 1;
        dpi.poolSizeCount = uint32_t(sizes.size());
        dpi.pPoolSizes = sizes.data();
        vk_check(vkCreateDescriptorPool(device, &dpi, nullptr, &pool_),
                 "creating a descriptor pool");
        VkDescriptorSetAllocateInfo dai{};
        dai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
        dai.descriptorPool = pool_;
        dai.descriptorSetCount = 1;
        dai.pSetLayouts = &set_layout_;
        vk_check(vkAllocateDescriptorSets(device, &dai, &set_), "allocating a descriptor set");
    } catch (...) {
        release();
        throw;
    }
}

PipelineBindings::~PipelineBindings() {
    release();
}

void PipelineBindings::release() {
    const VkDevice device = ctx_.device();
    if (pool_) vkDestroyDescriptorPool(device, pool_, nullptr); // frees the set
    if (layout_) vkDestroyPipelineLayout(device, layout_, nullptr);
    if (set_layout_) vkDestroyDescriptorSetLayout(device, set_layout_, nullptr);
    pool_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    set_layout_ = VK_NULL_HANDLE;
}

void PipelineBindings::write_buffer(uint32_t binding, const Buffer& buffer) {
    // The descriptor covers the whole buffer, which must fit the device's range.
    const uint32_t range = ctx_.limits().maxStorageBufferRange;
    const VkDeviceSize bytes = buffer.size();
    if (bytes > range)
        runtime_error("a {:.1f} MiB buffer (binding {}) exceeds the {:.1f} MiB storage-buffer "
                      "range of {}; lower --width/--height or use a smaller scene",
                      double(bytes) / 1048576.0, binding, double(range) / 1048576.0,
                      ctx_.info().name);
    const VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet w{};
    w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    w.dstSet = set_;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    w.pBufferInfo = &info;
    vkUpdateDescriptorSets(ctx_.device(), 1, &w, 0, nullptr);
}

void PipelineBindings::write_acceleration_structure(uint32_t binding,
                                                    VkAccelerationStructureKHR tlas) {
    VkWriteDescriptorSetAccelerationStructureKHR as{};
    as.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR;
    as.accelerationStructureCount = 1;
    as.pAccelerationStructures = &tlas;
    VkWriteDescriptorSet w{};
    w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    w.pNext = &as;
    w.dstSet = set_;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
    vkUpdateDescriptorSets(ctx_.device(), 1, &w, 0, nullptr);
}

void PipelineBindings::write_images(uint32_t binding, const std::vector<VkImageView>& views) {
    std::vector<VkDescriptorImageInfo> infos;
    for (VkImageView v : views)
        infos.push_back({VK_NULL_HANDLE, v, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
    VkWriteDescriptorSet w{};
    w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    w.dstSet = set_;
    w.dstBinding = binding;
    w.descriptorCount = uint32_t(infos.size());
    w.descriptorType = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    w.pImageInfo = infos.data();
    vkUpdateDescriptorSets(ctx_.device(), 1, &w, 0, nullptr);
}

void PipelineBindings::record_bind(VkCommandBuffer cmd, VkPipelineBindPoint bind_point,
                                   const void* push) const {
    vkCmdBindDescriptorSets(cmd, bind_point, layout_, 0, 1, &set_, 0, nullptr);
    if (push_bytes_ > 0) vkCmdPushConstants(cmd, layout_, stages_, 0, push_bytes_, push);
}

} // namespace tp
