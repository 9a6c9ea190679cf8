#include "vulkan_rt/device/shader_dispatch.h"

#include "vulkan_rt/device/barriers.h"
#include "vulkan_rt/device/compute_program.h"

namespace tp {

std::vector<std::vector<uint8_t>>
run_compute_shader(const VulkanContext& ctx, const uint32_t* spirv, size_t spirv_bytes,
                   const std::vector<HostBytes>& inputs, const std::vector<size_t>& output_bytes,
                   const void* push, uint32_t push_bytes, uint32_t groups,
                   const std::vector<const Buffer*>& device, uint32_t features,
                   const ImageArrayBinding* images) {
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                     VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                     VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    std::vector<Buffer> buffers;
    Uploader up(ctx);
    for (const HostBytes& in : inputs) buffers.push_back(up.add(in.data, in.bytes, usage));
    up.flush();
    std::vector<Buffer> outputs, readback;
    for (size_t bytes : output_bytes) {
        outputs.emplace_back(ctx, bytes, usage, false);
        readback.emplace_back(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    }
    std::vector<const Buffer*> bound = device;
    for (const Buffer& b : buffers) bound.push_back(&b);
    for (const Buffer& b : outputs) bound.push_back(&b);
    std::vector<BindingSlot> slots;
    for (uint32_t i = 0; i < bound.size(); ++i)
        if (bound[i]) slots.push_back({i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    RenderConstants constants{features};
    if (images) {
        slots.push_back(
            {images->binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, uint32_t(images->views.size())});
        constants.image_count = images->count;
    }
    ComputeProgram program(ctx, spirv, spirv_bytes, slots, push_bytes, constants, false);
    for (uint32_t i = 0; i < bound.size(); ++i)
        if (bound[i]) program.bind(i, *bound[i]);
    if (images) program.bind_images(images->binding, images->views);
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        for (const Buffer& b : outputs) vkCmdFillBuffer(cmd, b.handle(), 0, VK_WHOLE_SIZE, 0);
        record_compute_barrier(cmd);
        program.record_dispatch(cmd, push, groups, 1, 1);
        record_compute_barrier(cmd);
        for (size_t i = 0; i < outputs.size(); ++i) {
            const VkBufferCopy region{0, 0, output_bytes[i]};
            vkCmdCopyBuffer(cmd, outputs[i].handle(), readback[i].handle(), 1, &region);
        }
        record_host_read_barrier(cmd);
    });
    std::vector<std::vector<uint8_t>> result;
    for (size_t i = 0; i < outputs.size(); ++i) {
        const auto* p = static_cast<const uint8_t*>(readback[i].mapped());
        result.emplace_back(p, p + output_bytes[i]);
    }
    return result;
}

} // namespace tp
