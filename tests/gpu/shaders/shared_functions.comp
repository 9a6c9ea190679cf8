#version 460
// Runs run_function (function_table.h) on every input record: record i of `inputs` with
// function id `ids[i]` gives record i of `outputs`.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require

#include "function_table.h"

layout(local_size_x = 64) in;
layout(scalar, set = 0, binding = 0) readonly buffer Ids { uint ids[]; };
layout(scalar, set = 0, binding = 1) readonly buffer Inputs { FnIn inputs[]; };
layout(scalar, set = 0, binding = 2) writeonly buffer Outputs { FnOut outputs[]; };
layout(push_constant) uniform Count { uint count; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < count) outputs[i] = run_function(ids[i], inputs[i]);
}
