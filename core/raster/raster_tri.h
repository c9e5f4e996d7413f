// The per-triangle and per-pixel steps of the rasteriser, host-and-device: triangle set-up
// (camera space, near clip, projection, pixel bounds) and coverage of one pixel centre with the
// top-left fill rule and the 64-bit depth key. The CPU rasteriser bins the set-up triangles
// into tiles; the wavefront pipeline covers each triangle's bounds with an atomic minimum.
// Both give the same key for every pixel.
#pragma once

#include "core/raster/camera.h"
#include "core/raster/sample_window.h"
#include "core/scene/prepared_scene.h"

#include <cfloat>
#include <cstdint>
#include <cstring>

namespace sheaf {

struct ScreenTri {
    double x[3], y[3], iz[3]; // screen position and the depth attribute of each vertex
    double inv_area;
    uint32_t prim;
    int x0, y0, x1, y1; // pixel bounds, inclusive; x0 > x1 when empty
};

namespace raster_detail {

struct D3 {
    double x, y, z;
};

// std::min / std::max semantics (the first argument on ties and NaNs), on host and device.
SHEAF_HD_INLINE double dmin(double a, double b) {
    return b < a ? b : a;
}
SHEAF_HD_INLINE double dmax(double a, double b) {
    return a < b ? b : a;
}

// Sutherland-Hodgman against the plane z = near: a triangle becomes 0, 3 or 4 vertices.
SHEAF_HD_INLINE int clip_near(const D3 in[3], double near, D3 out[4]) {
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        const D3& a = in[i];
        const D3& b = in[(i + 1) % 3];
        const bool ain = a.z >= near, bin = b.z >= near;
        if (ain) out[n++] = a;
        if (ain != bin) {
            const double t = (near - a.z) / (b.z - a.z);
            out[n++] = {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, near};
        }
    }
    return n;
}

// Edges owned on a tie: with consistent orientation a shared edge appears once in each
// direction, so exactly one of its two triangles owns the pixels on it.
SHEAF_HD_INLINE bool owns_edge(double dx, double dy) {
    return dy > 0 || (dy == 0 && dx < 0);
}

template <class T> SHEAF_HD_INLINE void swap_values(T& a, T& b) {
    const T t = a;
    a = b;
    b = t;
}

} // namespace raster_detail

/// Triangle `prim` set up for the screen: out[0] and out[1] (a quad clipped by the near plane
/// becomes two); an entry with x0 > x1 covers nothing. `near` is raster_near's.
SHEAF_HD_INLINE void setup_triangle(const TriangleVerts& t, uint32_t prim, bool hidden,
                                    const CameraFrame& cam, double near, ScreenTri out[2]) {
    using namespace raster_detail;
    const int W = cam.width, H = cam.height;
    out[0].x0 = out[1].x0 = 1, out[0].x1 = out[1].x1 = 0;
    out[0].y0 = out[1].y0 = 1, out[0].y1 = out[1].y1 = 0; // the cover loops read these too
    if (hidden) return; // not seen by the camera
    const Vec3 v[3] = {t.a, t.b, t.c};
    D3 c[3];
    for (int i = 0; i < 3; ++i) {
        const double dx = double(v[i].x) - cam.origin.x, dy = double(v[i].y) - cam.origin.y,
                     dz = double(v[i].z) - cam.origin.z;
        c[i] = {dx * cam.right.x + dy * cam.right.y + dz * cam.right.z,
                dx * cam.up.x + dy * cam.up.y + dz * cam.up.z,
                dx * cam.forward.x + dy * cam.forward.y + dz * cam.forward.z};
    }
    // The near plane, per triangle: 1e-7 of its farthest vertex's distance, no nearer (a
    // vertex clipped nearer would project so far off the screen that the edge functions lose
    // the pixels), and never nearer than `near`. A scene's far geometry clips nothing near.
    double extent = 0;
    for (int i = 0; i < 3; ++i)
        extent = dmax(extent, dmax(fabs(c[i].x), dmax(fabs(c[i].y), fabs(c[i].z))));
    D3 poly[4];
    const int m = clip_near(c, cam.ortho ? near : dmax(near, 1e-7 * extent), poly);
    for (int k = 0; k + 2 < m; ++k) {
        const D3 q[3] = {poly[0], poly[k + 1], poly[k + 2]};
        ScreenTri s;
        for (int i = 0; i < 3; ++i) {
            // Inverse of CameraFrame::ndc. Perspective depth interpolates as 1/z in screen
            // space, orthographic depth as z.
            const double px = cam.ortho ? q[i].x : q[i].x / q[i].z;
            const double py = cam.ortho ? q[i].y : q[i].y / q[i].z;
            s.x[i] = (px / cam.half_x - cam.shift_x + 1.0) * 0.5 * W;
            s.y[i] = (1.0 - (py / cam.half_y - cam.shift_y)) * 0.5 * H;
            s.iz[i] = cam.ortho ? q[i].z : 1.0 / q[i].z;
        }
        double area =
            (s.x[1] - s.x[0]) * (s.y[2] - s.y[0]) - (s.x[2] - s.x[0]) * (s.y[1] - s.y[0]);
        if (area < 0) {
            swap_values(s.x[1], s.x[2]), swap_values(s.y[1], s.y[2]),
                swap_values(s.iz[1], s.iz[2]);
            area = -area;
        }
        s.prim = prim;
        s.x0 = s.x1 = 0, s.y0 = s.y1 = 0;
        if (!(area > 0) || !(area <= DBL_MAX)) { // empty, NaN or infinite
            s.x0 = 1, s.x1 = 0;
        } else {
            s.inv_area = 1.0 / area;
            const double minx = dmin(dmin(s.x[0], s.x[1]), s.x[2]),
                         maxx = dmax(dmax(s.x[0], s.x[1]), s.x[2]);
            const double miny = dmin(dmin(s.y[0], s.y[1]), s.y[2]),
                         maxy = dmax(dmax(s.y[0], s.y[1]), s.y[2]);
            // Clamped on both sides before the conversion: a triangle far off the screen has
            // bounds beyond int's range, whose conversion is undefined (found by the C ABI
            // fuzzer: -2.8e18). Off the screen, x0 > x1 or y0 > y1: empty.
            s.x0 = int(dmin(dmax(0.0, floor(minx - 0.5)), double(W)));
            s.x1 = int(dmax(dmin(double(W - 1), ceil(maxx - 0.5)), -1.0));
            s.y0 = int(dmin(dmax(0.0, floor(miny - 0.5)), double(H)));
            s.y1 = int(dmax(dmin(double(H - 1), ceil(maxy - 0.5)), -1.0));
        }
        out[k] = s;
    }
}

/// Cuts s's pixel bounds to the window's samples (region.*): empty (x0 > x1 or y0 > y1) when
/// the triangle covers none of them.
SHEAF_HD_INLINE void clip_to_window(ScreenTri& s, const SampleWindow& w) {
    if (s.x0 > s.x1 || s.y0 > s.y1) return;
    s.x0 = s.x0 > w.x ? s.x0 : w.x;
    s.y0 = s.y0 > w.y ? s.y0 : w.y;
    s.x1 = s.x1 < w.x + w.width - 1 ? s.x1 : w.x + w.width - 1;
    s.y1 = s.y1 < w.y + w.height - 1 ? s.y1 : w.y + w.height - 1;
    if (s.x0 > s.x1 || s.y0 > s.y1) s.x0 = 1, s.x1 = 0, s.y0 = 1, s.y1 = 0;
}

/// Whether the centre of pixel (x, y) is inside s (top-left rule); if so `key` is its depth
/// key: float depth bits << 32 | primitive, so the minimum is the nearest (ties: lower id).
SHEAF_HD_INLINE bool cover_pixel(const ScreenTri& s, int x, int y, bool ortho, uint64_t& key) {
    const double py = y + 0.5, px = x + 0.5;
    double w[3];
    bool inside = true;
    for (int e = 0; e < 3 && inside; ++e) {
        const int a = (e + 1) % 3, c = (e + 2) % 3; // edge a -> c, opposite vertex e
        const double dx = s.x[c] - s.x[a], dy = s.y[c] - s.y[a];
        w[e] = dx * (py - s.y[a]) - dy * (px - s.x[a]);
        inside = w[e] > 0 || (w[e] == 0 && raster_detail::owns_edge(dx, dy));
    }
    if (!inside) return false;
    const double iz = (w[0] * s.iz[0] + w[1] * s.iz[1] + w[2] * s.iz[2]) * s.inv_area;
    const float depth = float(ortho ? iz : 1.0 / iz);
    uint32_t bits;
    memcpy(&bits, &depth, 4);
    key = (uint64_t(bits) << 32) | s.prim;
    return true;
}

} // namespace sheaf
