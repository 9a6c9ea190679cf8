#include "vulkan_rt/compute_mode/bvh_buffers.h"

namespace tp {

BvhBuffers upload_bvh(const VulkanContext& ctx, const BvhBuild& bvh) {
    Uploader up(ctx);
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    const bool wide = bvh.layout == BvhLayout::wide;
    BvhBuffers b{wide ? up.add(bvh.wide_nodes, storage) : up.add(bvh.nodes, storage),
                 wide ? up.add(bvh.wide_triangles.words(), storage)
                      : up.add(bvh.triangles, storage)};
    up.flush();
    return b;
}

} // namespace tp
