// The camera as the pipeline uses it: an orthonormal basis and the pixel-to-ray mapping shared
// by the rasteriser and by ray-cast primary rays. Perspective or orthographic, with lens shift.
#pragma once

#include "core/geometry/ray.h"
#include "core/scene/scene.h"

#include <cfloat>

namespace sheaf {

struct CameraFrame {
    Vec3 origin, forward, right, up;
    bool ortho = false;
    // Perspective: tangents of the half field of view; orthographic: half the view extent.
    float half_y = 1, half_x = 1;
    float shift_x = 0, shift_y = 0; // in normalised device units (2 = one image width/height)
    int width = 1, height = 1;

    /// Normalised device coordinates of the centre of pixel (x, y); y = 0 is the top row.
    SHEAF_HD void ndc(int x, int y, float& sx, float& sy) const {
        sx = (2.0f * (float(x) + 0.5f) / float(width) - 1.0f + shift_x) * half_x;
        sy = (1.0f - 2.0f * (float(y) + 0.5f) / float(height) + shift_y) * half_y;
    }

    /// The primary ray through the centre of pixel (x, y).
    SHEAF_HD Ray pixel_ray(int x, int y) const {
        float sx, sy;
        ndc(x, y, sx, sy);
        Ray r;
        if (ortho) {
            r.origin = origin + right * sx + up * sy;
            r.dir = forward;
        } else {
            r.origin = origin;
            r.dir = normalize(forward + right * sx + up * sy);
        }
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
    if (c.mirror) f.right = -f.right; // x across the image runs the other way
    f.ortho = c.projection == Projection::Orthographic;
    f.half_y = f.ortho ? 0.5f * c.ortho_height : tanf(c.fov_y_degrees * kPi / 360.0f);
    f.half_x = f.half_y * (c.aspect > 0 ? c.aspect : float(width) / float(height));
    f.shift_x = 2.0f * c.shift_x;
    f.shift_y = 2.0f * c.shift_y;
    f.width = width;
    f.height = height;
    return f;
}

} // namespace sheaf
