// Pinhole camera. Thesis eq. 2.48 maps the pixel to u, v in [-1, 1] and the ray direction to
// side * u + tan(theta) * v * up + d with theta = FOVy / 2; that is exact only for square images.
// Generalised: the horizontal half-extent of the image plane at distance 1 is
// tan(theta) * aspect, so r = d + u tan(theta) aspect side + v tan(theta) up, with v growing
// upwards while pixel y grows downwards (docs/design.md: pixel (x, y) with y down).
#ifndef TP_SHARED_CAMERA_H
#define TP_SHARED_CAMERA_H

#include "math.h"
#include "types.h"

TP_NAMESPACE_BEGIN

// Right-handed, Y-up: right = forward x up. The host rejects eye == target and an up vector
// parallel to the view direction before calling this.
inline Camera camera_make(vec3 eye, vec3 target, vec3 up, float fov_y_degrees, uint width,
                          uint height) {
    Camera c;
    c.eye = eye;
    c.forward = normalize(target - eye);
    c.right = normalize(cross(c.forward, up));
    c.up = cross(c.right, c.forward);
    c.tan_half_fov_y = tan(0.5f * fov_y_degrees * (PI / 180.0f));
    c.width = width;
    c.height = height;
    c.aspect = float(width) / float(height);
    return c;
}

// Direction through the continuous film position (px, py), in pixels from the top-left corner.
inline vec3 camera_direction(Camera c, float px, float py) {
    float u = 2.0f * px / float(c.width) - 1.0f;
    float v = 1.0f - 2.0f * py / float(c.height);
    return normalize(c.forward + (u * c.tan_half_fov_y * c.aspect) * c.right +
                     (v * c.tan_half_fov_y) * c.up);
}

TP_NAMESPACE_END

#endif // TP_SHARED_CAMERA_H
