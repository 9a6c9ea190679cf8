// The debug variant's passes other than rendering (shared/path_log.h, DEBUG_PASS_*), for every
// entry point: the AOVs of every pixel, and the path log of the debug pixel. Include after
// render_items.glsl. The entry point calls debug_pass for debug_header.pass != DEBUG_PASS_RENDER.
#ifndef TP_SHADERS_DEBUG_PASS_GLSL
#define TP_SHADERS_DEBUG_PASS_GLSL

#include "debug.glsl"
#include "integrator.glsl"

void debug_pass(uvec2 pixel) {
    if (pixel.x >= params.camera.width || pixel.y >= batch.row_end) return;
    if (debug_header.pass == DEBUG_PASS_AOV) {
        aovs[pixel.y * params.camera.width + pixel.x] =
            primary_aov(camera_center_ray(params.camera, pixel.x, pixel.y));
        return;
    }
    if (pixel.x != debug_header.pixel_x || pixel.y != debug_header.pixel_y) return;
    // One sample per dispatch (vulkan_rt/render_loop/render_loop.cpp), well inside lavapipe's loop
    // budget.
    g_path_log_on = true;
    for (uint s = batch.sample_begin; s < batch.sample_begin + batch.sample_count; ++s) {
        RayCounts rays;
        rays.camera = 0u;
        rays.extension = 0u;
        rays.shadow = 0u;
        path_radiance(pixel.x, pixel.y, s, rays);
    }
}

#endif // TP_SHADERS_DEBUG_PASS_GLSL
