#version 460
// The glTF material's extremes in GLSL (stress/pbr_cases.cpp): the shading normal bent by a normal
// map texel (surface.h) and turned to the viewer, then pbr_sample, pbr_eval and pbr_pdf
// (common/shared/pbr.h) at it, for the host's inputs; the host applies the same checks as to the
// C++ results.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require

#include "shared/pbr.h"
#include "shared/surface.h"

struct PbrInput {
    Material m;
    vec3 ng; // the geometric normal, and the shading normal before the normal map
    float u_lobe;
    vec3 wo;
    float u_dir0;
    vec3 wi; // a direction to evaluate f and pdf at
    float u_dir1;
    vec3 tangent;
    float normal_scale;
    vec3 bitangent;
    uint use_map; // 1: bend the normal by `texel`
    vec3 texel;
    float pad0;
};

struct PbrOutput {
    vec3 sample_wi;
    float sample_pdf;
    vec3 sample_weight;
    uint sample_lobe;
    vec3 f;    // pbr_eval(ns, wo, wi)
    float pdf; // pbr_pdf(ns, wo, wi)
    vec3 ns;   // the shading normal the functions saw
    float pad0;
};

layout(local_size_x = 64) in;
layout(push_constant, scalar) uniform Push { uint count; };
layout(scalar, set = 0, binding = 0) readonly buffer InBuffer { PbrInput inputs[]; };
layout(scalar, set = 0, binding = 1) writeonly buffer OutBuffer { PbrOutput outputs[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= count) return;
    PbrInput a = inputs[i];
    SurfacePoint sp;
    sp.p = vec3(0.0f);
    sp.p_error = vec3(0.0f);
    sp.ng = a.ng;
    sp.ns = a.ng;
    sp.uv = vec2(0.0f);
    sp.uv1 = vec2(0.0f);
    sp.tangent = a.tangent;
    sp.bitangent = a.bitangent;
    if (a.use_map != 0u) surface_apply_normal_map(sp, a.texel, a.normal_scale);
    surface_face_viewer(sp, a.wo);
    BsdfSample s = pbr_sample(a.m, sp.ns, a.wo, a.u_lobe, vec2(a.u_dir0, a.u_dir1));
    PbrOutput o;
    o.sample_wi = s.wi;
    o.sample_pdf = s.pdf;
    o.sample_weight = s.weight;
    o.sample_lobe = s.lobe;
    o.f = pbr_eval(a.m, sp.ns, a.wo, a.wi);
    o.pdf = pbr_pdf(a.m, sp.ns, a.wo, a.wi);
    o.ns = sp.ns;
    o.pad0 = 0.0f;
    outputs[i] = o;
}
