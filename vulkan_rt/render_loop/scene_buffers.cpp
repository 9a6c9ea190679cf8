#include "vulkan_rt/render_loop/scene_buffers.h"

namespace tp {

std::vector<BindingSlot> interface_slots(uint32_t count, bool images, bool tlas) {
    std::vector<BindingSlot> slots;
    for (uint32_t b = 0; b < count; ++b) {
        if (b == BINDING_IMAGES) {
            if (images) slots.push_back({b, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, IMAGE_SLOTS});
        } else if (tlas && b == BINDING_TLAS) {
            slots.push_back({b, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR});
        } else {
            slots.push_back({b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
        }
    }
    return slots;
}

SceneBuffers upload_scene(const VulkanContext& ctx, const FlatScene& scene,
                          const RenderParams& params, const std::vector<uint32_t>& mesh_bvh_roots,
                          VkBufferUsageFlags geometry_usage, uint32_t features) {
    bool normals = false, uvs = false;
    for (const MeshInfo& m : scene.meshes) {
        normals = normals || (m.flags & MESH_HAS_NORMALS);
        uvs = uvs || (m.flags & MESH_HAS_UVS);
    }
    std::vector<MeshInfo> meshes = scene.meshes;
    for (size_t i = 0; i < mesh_bvh_roots.size(); ++i) meshes[i].bvh_root = mesh_bvh_roots[i];

    check_scene_images(ctx, scene, features); // before anything is uploaded
    SceneBuffers sb;
    Uploader up(ctx);
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    auto put = [&](uint32_t slot, const void* data, size_t bytes, VkBufferUsageFlags usage) {
        sb.slots[slot] = up.add(data, bytes, usage);
        sb.bytes += bytes;
    };
    auto put_if = [&](uint32_t slot, bool used, const auto& v) {
        put(slot, v.data(), used ? v.size() * sizeof(v[0]) : 0, storage);
    };
    put(BINDING_PARAMS, &params, sizeof(params), storage);
    put_if(BINDING_MATERIALS, true, scene.materials);
    put_if(BINDING_INSTANCES, true, scene.instances);
    put_if(BINDING_MESHES, true, meshes);
    put(BINDING_POSITIONS, scene.positions.data(), scene.positions.size() * sizeof(vec3),
        storage | geometry_usage);
    put_if(BINDING_NORMALS, normals, scene.normals);
    // The shaders read uvs only to look textures up (shared/scene_access.h), tangents only for
    // normal maps.
    const bool textures = feature_on(features, FEATURE_TEXTURES);
    put_if(BINDING_UVS, uvs && textures, scene.uvs);
    put_if(BINDING_UVS1, textures, scene.uvs1);
    put_if(BINDING_TANGENTS, feature_on(features, FEATURE_NORMAL_MAPS), scene.tangents);
    put(BINDING_TRIANGLES, scene.triangles.data(), scene.triangles.size() * sizeof(uvec3),
        storage | geometry_usage);
    put_if(BINDING_LIGHTS, true, scene.lights);
    put_if(BINDING_LIGHT_TABLE, true, scene.light_table);
    const bool env_map = feature_on(features, FEATURE_ENV_MAP);
    put_if(BINDING_TEXTURES, textures || env_map, scene.textures);
    put_if(BINDING_TEXTURE_SLOTS, textures, scene.texture_slots);
    put_if(BINDING_ENV_TABLE, env_map, scene.env_table);
    up.flush();
    sb.images = upload_scene_images(ctx, scene, features);
    sb.bytes += sb.images.bytes;
    return sb;
}

} // namespace tp
