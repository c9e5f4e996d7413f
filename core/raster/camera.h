// The perspective camera as the pipeline uses it: an orthonormal basis and the pixel-to-ray
// mapping shared by the rasteriser and by ray-cast primary rays.
#pragma once

#include "core/geometry/ray.h"
#include "core/scene/scene.h"

#include <cfloat>

namespace sheaf {

struct CameraFrame {
    Vec3 origin, forward, right, up;
    float tan_half_y = 1, tan_half_x = 1;
    int width = 1, height = 1;

    /// The primary ray through the centre of pixel (x, y); y = 0 is the top row.
    SHEAF_HD Ray pixel_ray(int x, int y) const {
        const float sx = (2.0f * (float(x) + 0.5f) / float(width) - 1.0f) * tan_half_x;
        const float sy = (1.0f - 2.0f * (float(y) + 0.5f) / float(height)) * tan_half_y;
        Ray r;
        r.origin = origin;
        r.dir = normalize(forward + right * sx + up * sy);
        r.tmin = 0.0f;
        r.tmax = FLT_MAX;
        return r;
    }
};

inline CameraFrame make_camera_frame(const Camera& c, int width, int height) {
    CameraFrame f;
    f.origin = c.position;
    f.forward = normalize(c.look_at - c.position);
    f.right = normalize(cross(f.forward, c.up));
    f.up = cross(f.right, f.forward);
    f.tan_half_y = tanf(c.fov_y_degrees * kPi / 360.0f);
    f.tan_half_x = f.tan_half_y * float(width) / float(height);
    f.width = width;
    f.height = height;
    return f;
}

} // namespace sheaf
