// The pipeline barriers of a render: between a batch's shader writes and what reads them next
// (the next batch, the read-back copy), and from a read-back copy to the host.
#pragma once

#include <vulkan/vulkan.h>

namespace tp {

// Makes every shader write of `shader_stage` (compute, or ray tracing in pipeline mode) and
// every transfer write before it visible to every such shader read or write and transfer
// after it.
void record_shader_barrier(VkCommandBuffer cmd, VkPipelineStageFlags shader_stage);

// record_shader_barrier for compute shaders.
void record_compute_barrier(VkCommandBuffer cmd);

// Makes transfer writes (a read-back copy) visible to the host once the submission completes.
void record_host_read_barrier(VkCommandBuffer cmd);

} // namespace tp
