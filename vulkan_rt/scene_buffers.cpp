#include "vulkan_rt/scene_buffers.h"

#include "shaders/interface.h"

namespace tp {

SceneBuffers upload_scene(const VulkanContext& ctx, const FlatScene& scene,
                          const RenderParams& params, const BvhBuild& bvh) {
    static_assert(BINDING_BVH_TRIS + 1 == 15, "SceneBuffers::slots covers the scene bindings");
    bool normals = false, uvs = false;
    for (const MeshInfo& m : scene.meshes) {
        normals = normals || (m.flags & MESH_HAS_NORMALS);
        uvs = uvs || (m.flags & MESH_HAS_UVS);
    }
    std::vector<MeshInfo> meshes = scene.meshes;
    for (size_t i = 0; i < meshes.size(); ++i) meshes[i].bvh_root = bvh.mesh_roots[i];

    SceneBuffers sb;
    Uploader up(ctx);
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    auto put = [&](uint32_t slot, const void* data, size_t bytes) {
        sb.slots[slot] = up.add(data, bytes, usage);
        sb.bytes += bytes;
    };
    auto put_if = [&](uint32_t slot, bool used, const auto& v) {
        put(slot, v.data(), used ? v.size() * sizeof(v[0]) : 0);
    };
    put(BINDING_PARAMS, &params, sizeof(params));
    put_if(BINDING_MATERIALS, true, scene.materials);
    put_if(BINDING_INSTANCES, true, scene.instances);
    put_if(BINDING_MESHES, true, meshes);
    put_if(BINDING_POSITIONS, true, scene.positions);
    put_if(BINDING_NORMALS, normals, scene.normals);
    put_if(BINDING_UVS, uvs, scene.uvs);
    put_if(BINDING_TRIANGLES, true, scene.triangles);
    put_if(BINDING_LIGHTS, true, scene.lights);
    put_if(BINDING_LIGHT_TABLE, true, scene.light_table);
    put_if(BINDING_TEXTURES, true, scene.textures);
    put_if(BINDING_TEXELS, true, scene.texels);
    put_if(BINDING_ENV_TABLE, true, scene.env_table);
    put_if(BINDING_BVH_NODES, true, bvh.nodes);
    put_if(BINDING_BVH_TRIS, true, bvh.triangles);
    up.flush();
    return sb;
}

} // namespace tp
