// The camera as the pipeline uses it: an orthonormal basis and the pixel-to-ray mapping shared
// by the rasteriser and by ray-cast primary rays. Perspective or orthographic, with lens shift;
// POV-Ray's other camera types (fisheye, panoramic, cylinder ...) map pixels to rays that no
// plane holds, so their primary visibility is traced (`traced`) with the same rays.
#pragma once

#include "core/geometry/ray.h"
#include "core/math/hd_math.h"
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
    // Traced projections: which one, the angles in radians and POV-Ray's lengths of right, up
    // and direction (Camera).
    Projection projection = Projection::Perspective;
    bool traced = false;
    int32_t normal = -1; // Camera::normal: primary rays tilted (core/shading/frame_kernels.h)
    float angle = 0, v_angle = 0;
    float right_length = 1, up_length = 1, direction_length = 1;
    // Depth of field (Camera::lens_radius): the lens, the distance to the sharp plane, and the
    // anti-aliasing samples per axis, so that (x, y) tells the pixel and its sample apart.
    float lens_radius = 0, focal_distance = 0;
    int samples = 1;
    // Projection::Mesh: Camera's mesh_* (the faces are the scene's: core/shading/mesh_camera.h).
    uint32_t mesh_rays = 1;
    uint8_t mesh_distribution = 0;
    bool mesh_smooth = false, mesh_reverse = false;
    float mesh_offset = 0;

    /// The point of the lens that sample (x, y) leaves from, as an offset from the eye: the
    /// pixel's samples take the cells of an n x n grid over the lens (mapped onto the disc by
    /// Shirley and Chiu's concentric map) in an order and with a jitter drawn from the pixel's
    /// hash, so that neighbouring pixels do not repeat one pattern. The same on every backend.
    SHEAF_HD Vec3 lens_offset(int x, int y) const {
        const int n = samples > 0 ? samples : 1;
        const uint32_t px = uint32_t(x / n), py = uint32_t(y / n);
        const uint32_t cells = uint32_t(n * n), sub = uint32_t(x % n + n * (y % n));
        auto mix = [](uint32_t h) {
            h ^= h >> 16, h *= 0x7feb352dU, h ^= h >> 15, h *= 0x846ca68bU, h ^= h >> 16;
            return h;
        };
        const uint32_t hp = mix(px * 0x9E3779B1U ^ mix(py + 0x632BE5ABU));
        const uint32_t k = (sub + hp) % cells, hs = mix(hp ^ (sub * 0x85EBCA77U));
        const float ju = float(hs & 0xFFFFu) * (1.0f / 65536.0f);
        const float jv = float(hs >> 16) * (1.0f / 65536.0f);
        const float a = 2.0f * (float(k % uint32_t(n)) + ju) / float(n) - 1.0f;
        const float b = 2.0f * (float(k / uint32_t(n)) + jv) / float(n) - 1.0f;
        float rad = 0, phi = 0;
        if (fabsf(a) > fabsf(b)) {
            rad = a, phi = 0.25f * kPi * (b / a);
        } else if (b != 0) {
            rad = b, phi = 0.5f * kPi - 0.25f * kPi * (a / b);
        }
        rad *= lens_radius;
        return right * (rad * hdm::cosf(phi)) + up * (rad * hdm::sinf(phi));
    }

    /// Normalised device coordinates of the centre of pixel (x, y); y = 0 is the top row.
    SHEAF_HD void ndc(int x, int y, float& sx, float& sy) const {
        sx = (2.0f * (float(x) + 0.5f) / float(width) - 1.0f + shift_x) * half_x;
        sy = (1.0f - 2.0f * (float(y) + 0.5f) / float(height) + shift_y) * half_y;
    }

    /// The primary ray through the centre of pixel (x, y); false where the projection has none
    /// (outside a fisheye's circle, below an omnimax dome's edge): the pixel stays black. A
    /// camera normal, and a mesh camera's rays, need the scene: see camera_ray and primary_ray
    /// (core/shading/frame_kernels.h); here a mesh camera has none.
    SHEAF_HD bool camera_ray(int x, int y, Ray& r) const {
        // A surface through the eye itself is not seen (POV-Ray ignores hits nearer than
        // 1e-4): a camera on a box's face looks into the box (interior/media/media1.pov).
        // Rounding of the eye's coordinates, about 1e-7 of them, decides nothing then.
        r.tmin = 1e-5f * hdm::fmaxf(1.0f, hdm::fmaxf(fabsf(origin.x),
                                                     hdm::fmaxf(fabsf(origin.y), fabsf(origin.z))));
        r.tmax = FLT_MAX;
        r.origin = origin;
        if (!traced_projection(projection)) {
            float sx, sy;
            ndc(x, y, sx, sy);
            const Vec3 d = ortho ? forward : forward + right * sx + up * sy;
            if (ortho) r.origin = origin + right * sx + up * sy;
            if (lens_radius > 0) { // through the pixel's point on the sharp plane
                const Vec3 sharp = r.origin + d * focal_distance;
                r.origin = r.origin + lens_offset(x, y);
                r.dir = normalize(sharp - r.origin);
            } else {
                r.dir = ortho ? d : normalize(d);
            }
            return true;
        }
        // u across the image and v up it, each from -1/2 to 1/2 (POV-Ray's x0 and y0).
        const float u = (float(x) + 0.5f) / float(width) - 0.5f + 0.5f * shift_x;
        const float v = 0.5f - (float(y) + 0.5f) / float(height) + 0.5f * shift_y;
        Vec3 d;
        switch (projection) {
        case Projection::Mesh:
            return false;
        case Projection::Fisheye:
        case Projection::Omnimax: {
            float px = 2.0f * u, py = 2.0f * v;
            if (projection == Projection::Fisheye) {
                px *= right_length, py *= up_length;
            } else {
                // POV-Ray fits the dome's circle to the image's aspect ratio.
                constexpr float kDome = 1.283458f;
                const float aspect = right_length / up_length;
                if (aspect > kDome)
                    px *= aspect / kDome, py = (py - 1.0f) / kDome + 1.0f;
                else if (aspect > 1.0f)
                    py = (py - 1.0f) / aspect + 1.0f;
                else
                    py /= aspect;
            }
            const float rad = sqrtf(px * px + py * py);
            if (!(rad <= 1.0f)) return false;
            const float phi = rad > 0 ? hdm::atan2f(py, px) : 0.0f;
            const float theta =
                projection == Projection::Fisheye
                    ? rad * 0.5f * angle
                    : rad * (1.411269f + rad * rad * (-0.09439f + 0.25674f * rad * rad));
            const float st = hdm::sinf(theta), ct = hdm::cosf(theta);
            // An omnimax dome sees no lower than 45 degrees below its axis.
            if (projection == Projection::Omnimax && hdm::sinf(phi) * st < -ct) return false;
            d = right * (hdm::cosf(phi) * st) + up * (hdm::sinf(phi) * st) + forward * ct;
            break;
        }
        case Projection::Panoramic: {
            const float a = (0.5f - u) * kPi, b = v * kPi;
            const float t =
                fabsf(0.5f * kPi - fabsf(b)) < 1e-6f ? copysignf(1e7f, b) : hdm::tanf(b);
            d = right * (hdm::cosf(a) * right_length) + up * (t * up_length) +
                forward * (hdm::sinf(a) * direction_length);
            break;
        }
        case Projection::UltraWideAngle: {
            const float a = u * angle, b = v * angle * (up_length / right_length);
            d = right * hdm::sinf(a) + up * hdm::sinf(b) + forward * (hdm::cosf(a) * hdm::cosf(b));
            break;
        }
        case Projection::Cylinder1:
        case Projection::Cylinder2:
        case Projection::Cylinder3:
        case Projection::Cylinder4: {
            // 1 and 3: a vertical cylinder (turning across, running up); 2 and 4: a horizontal
            // one. 1 and 2 tilt the ray along the axis, 3 and 4 move the eye along it.
            const bool vertical =
                projection == Projection::Cylinder1 || projection == Projection::Cylinder3;
            const Vec3 turn = vertical ? right : up, axis = vertical ? up : right;
            const float a = (vertical ? u : v) * angle;
            const float h = vertical ? v * up_length : u * right_length;
            d = turn * hdm::sinf(a) + forward * hdm::cosf(a);
            if (projection == Projection::Cylinder1 || projection == Projection::Cylinder2)
                d = d + axis * h;
            else
                r.origin = origin + axis * h;
            break;
        }
        default: { // Spherical: latitude v, then longitude u about up
            const float a = u * angle, b = v * v_angle;
            d = (forward * hdm::cosf(a) + right * hdm::sinf(a)) * hdm::cosf(b) + up * hdm::sinf(b);
            break;
        }
        }
        const float len = length(d);
        if (!(len > 0) || !(len <= FLT_MAX)) return false;
        r.dir = d / len;
        return true;
    }

    /// The primary ray through the centre of pixel (x, y) of a projection that has one there.
    SHEAF_HD Ray pixel_ray(int x, int y) const {
        Ray r;
        camera_ray(x, y, r);
        return r;
    }
};

/// The frame of camera c for a width x height grid of samples, `samples` x `samples` of them to
/// a pixel (anti-aliasing).
inline CameraFrame make_camera_frame(const Camera& c, int width, int height, int samples = 1) {
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
    f.projection = c.projection;
    f.traced = traced_projection(c.projection) || c.normal >= 0 || c.lens_radius > 0;
    f.lens_radius = c.lens_radius;
    f.focal_distance = c.focal_distance;
    f.samples = samples;
    f.normal = c.normal;
    f.angle = c.angle_degrees * kPi / 180.0f;
    f.v_angle = c.v_angle_degrees * kPi / 180.0f;
    f.right_length = c.right_length;
    f.up_length = c.up_length;
    f.direction_length = c.direction_length;
    f.mesh_rays = c.mesh_rays;
    f.mesh_distribution = c.mesh_distribution;
    f.mesh_smooth = c.mesh_smooth;
    f.mesh_reverse = c.mesh_reverse;
    f.mesh_offset = c.mesh_offset;
    return f;
}

} // namespace sheaf
