// The scene and film buffers of descriptor set 0 (slots in interface.h), as the render shaders
// see them. Every block uses the scalar layout, so the arrays are byte-for-byte the C++
// vectors of FlatScene. The acceleration structure's bindings belong to the trace include
// (trace_bvh.glsl: slots 16 and 17), the scene's images to their one reader
// (scene_access.glsl: slot 15).
#ifndef TP_SHADERS_BINDINGS_GLSL
#define TP_SHADERS_BINDINGS_GLSL

#extension GL_EXT_scalar_block_layout : require

#include "interface.h"
#include "shared/types.h"

layout(scalar, set = 0, binding = BINDING_PARAMS) readonly buffer ParamsBuffer {
    RenderParams params;
};
layout(scalar, set = 0, binding = BINDING_MATERIALS) readonly buffer MaterialBuffer {
    Material materials[];
};
layout(scalar, set = 0, binding = BINDING_INSTANCES) readonly buffer InstanceBuffer {
    Instance instances[];
};
layout(scalar, set = 0, binding = BINDING_MESHES) readonly buffer MeshBuffer {
    MeshInfo meshes[];
};
layout(scalar, set = 0, binding = BINDING_POSITIONS) readonly buffer PositionBuffer {
    vec3 positions[];
};
layout(scalar, set = 0, binding = BINDING_NORMALS) readonly buffer NormalBuffer {
    vec3 normals[];
};
layout(scalar, set = 0, binding = BINDING_UVS) readonly buffer UvBuffer {
    vec2 uvs[];
};
layout(scalar, set = 0, binding = BINDING_TRIANGLES) readonly buffer TriangleBuffer {
    uvec3 triangles[];
};
layout(scalar, set = 0, binding = BINDING_LIGHTS) readonly buffer LightBuffer {
    Light lights[];
};
layout(scalar, set = 0, binding = BINDING_LIGHT_TABLE) readonly buffer LightTableBuffer {
    AliasEntry light_table[];
};
layout(scalar, set = 0, binding = BINDING_TEXTURES) readonly buffer TextureBuffer {
    TextureInfo textures[];
};
layout(scalar, set = 0, binding = BINDING_TEXTURE_SLOTS) readonly buffer TextureSlotBuffer {
    TextureSlot texture_slots[];
};
layout(scalar, set = 0, binding = BINDING_UVS1) readonly buffer Uv1Buffer {
    vec2 uvs1[];
};
layout(scalar, set = 0, binding = BINDING_TANGENTS) readonly buffer TangentBuffer {
    vec4 tangents[];
};
layout(scalar, set = 0, binding = BINDING_ENV_TABLE) readonly buffer EnvTableBuffer {
    AliasEntry env_table[];
};
layout(scalar, set = 0, binding = BINDING_ACCUM) buffer AccumBuffer {
    PixelAccum accum[];
};
layout(scalar, set = 0, binding = BINDING_COUNTERS) buffer CounterBuffer {
    uint counters[];
};
layout(scalar, set = 0, binding = BINDING_SAMPLES) buffer SampleBuffer {
    vec4 sample_radiance[]; // by work item (interface.h)
};

layout(push_constant, scalar) uniform BatchBlock {
    BatchParams batch;
};

#endif // TP_SHADERS_BINDINGS_GLSL
