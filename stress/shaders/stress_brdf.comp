#version 460
// BRDF extremes in GLSL (stress/brdf_cases.cpp): the shared modified-Phong functions
// (common/shared/brdf.h) evaluated on the device for the host's inputs; the host applies the
// same checks as to the C++ results.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require

#include "shared/brdf.h"

struct BrdfInput {
    vec3 kd;
    float ns;
    vec3 ks;
    float u_lobe;
    vec3 n;
    float u_dir0;
    vec3 wo;
    float u_dir1;
    vec3 wi; // a direction to evaluate f and pdf at
    float pad0;
};

struct BrdfOutput {
    vec3 sample_wi;
    float sample_pdf;
    vec3 sample_weight;
    uint sample_lobe;
    vec3 f;    // phong_eval(wo, wi)
    float pdf; // phong_pdf(wo, wi)
};

layout(local_size_x = 64) in;
layout(push_constant, scalar) uniform Push { uint count; };
layout(scalar, set = 0, binding = 0) readonly buffer InBuffer { BrdfInput inputs[]; };
layout(scalar, set = 0, binding = 1) writeonly buffer OutBuffer { BrdfOutput outputs[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= count) return;
    BrdfInput a = inputs[i];
    BsdfSample s = phong_sample(a.kd, a.ks, a.ns, a.n, a.wo, a.u_lobe, vec2(a.u_dir0, a.u_dir1));
    BrdfOutput o;
    o.sample_wi = s.wi;
    o.sample_pdf = s.pdf;
    o.sample_weight = s.weight;
    o.sample_lobe = s.lobe;
    o.f = phong_eval(a.kd, a.ks, a.ns, a.n, a.wo, a.wi);
    o.pdf = phong_pdf(a.kd, a.ks, a.ns, a.n, a.wo, a.wi);
    outputs[i] = o;
}
