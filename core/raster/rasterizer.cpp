#include "core/raster/rasterizer.h"

#include "core/base/parallel.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sheaf {
namespace {

struct D3 {
    double x, y, z;
};

struct ScreenTri {
    double x[3], y[3], iz[3]; // screen position and the depth attribute of each vertex
    double inv_area;
    uint32_t prim;
    int x0, y0, x1, y1; // pixel bounds, inclusive; x0 > x1 when empty
};

constexpr int kTile = 32;

// Sutherland-Hodgman against the plane z = near: a triangle becomes 0, 3 or 4 vertices.
int clip_near(const D3 in[3], double near, D3 out[4]) {
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
bool owns_edge(double dx, double dy) {
    return dy > 0 || (dy == 0 && dx < 0);
}

} // namespace

void rasterize(const PreparedScene& scene, const CameraFrame& cam, std::vector<uint64_t>& vis) {
    const int W = cam.width, H = cam.height;
    vis.assign(size_t(W) * H, kEmptyPixel);
    const size_t n = scene.triangle_count(); // analytic primitives are ray-cast by the caller
    if (n == 0) return;

    double extent = 1.0 + length(cam.origin);
    for (const Sphere& s : scene.object_sphere) // unbounded objects (planes) do not count
        if (std::isfinite(s.radius)) extent = std::max(extent, double(s.radius) + length(s.center));
    // Orthographic views start at the camera plane; perspective ones just in front of the eye.
    const double near = cam.ortho ? 0.0 : 1e-7 * extent;

    // 1. Set-up: camera space, near clip, projection. A clipped quad becomes two triangles.
    std::vector<ScreenTri> tris(2 * n);
    parallel_for("raster.setup", n, [&](size_t p) {
        tris[2 * p].x0 = tris[2 * p + 1].x0 = 1, tris[2 * p].x1 = tris[2 * p + 1].x1 = 0;
        if (scene.prim_flag(uint32_t(p), kNoImage)) return; // not seen by the camera
        const TriangleVerts& t = scene.tris[p];
        const Vec3 v[3] = {t.a, t.b, t.c};
        D3 c[3];
        for (int i = 0; i < 3; ++i) {
            const double dx = double(v[i].x) - cam.origin.x, dy = double(v[i].y) - cam.origin.y,
                         dz = double(v[i].z) - cam.origin.z;
            c[i] = {dx * cam.right.x + dy * cam.right.y + dz * cam.right.z,
                    dx * cam.up.x + dy * cam.up.y + dz * cam.up.z,
                    dx * cam.forward.x + dy * cam.forward.y + dz * cam.forward.z};
        }
        D3 poly[4];
        const int m = clip_near(c, near, poly);
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
                std::swap(s.x[1], s.x[2]), std::swap(s.y[1], s.y[2]), std::swap(s.iz[1], s.iz[2]);
                area = -area;
            }
            s.prim = uint32_t(p);
            s.x0 = s.x1 = 0, s.y0 = s.y1 = 0;
            if (!(area > 0) || !std::isfinite(area)) {
                s.x0 = 1, s.x1 = 0;
            } else {
                s.inv_area = 1.0 / area;
                const double minx = std::min({s.x[0], s.x[1], s.x[2]}),
                             maxx = std::max({s.x[0], s.x[1], s.x[2]});
                const double miny = std::min({s.y[0], s.y[1], s.y[2]}),
                             maxy = std::max({s.y[0], s.y[1], s.y[2]});
                s.x0 = int(std::max(0.0, std::floor(minx - 0.5)));
                s.x1 = int(std::min(double(W - 1), std::ceil(maxx - 0.5)));
                s.y0 = int(std::max(0.0, std::floor(miny - 0.5)));
                s.y1 = int(std::min(double(H - 1), std::ceil(maxy - 0.5)));
            }
            tris[2 * p + k] = s;
        }
    });

    // 2. Binning into screen tiles.
    const int tx = (W + kTile - 1) / kTile, ty = (H + kTile - 1) / kTile;
    std::vector<std::vector<uint32_t>> bins(size_t(tx) * ty);
    for (uint32_t i = 0; i < tris.size(); ++i) {
        const ScreenTri& s = tris[i];
        if (s.x0 > s.x1 || s.y0 > s.y1) continue;
        for (int by = s.y0 / kTile; by <= s.y1 / kTile; ++by)
            for (int bx = s.x0 / kTile; bx <= s.x1 / kTile; ++bx)
                bins[size_t(by) * tx + bx].push_back(i);
    }

    // 3. Coverage and depth, one tile per task: no two tasks write the same pixel.
    parallel_for("raster.tiles", bins.size(), [&](size_t b) {
        const int bx = int(b % tx) * kTile, by = int(b / tx) * kTile;
        for (uint32_t i : bins[b]) {
            const ScreenTri& s = tris[i];
            const int x0 = std::max(s.x0, bx), x1 = std::min(s.x1, bx + kTile - 1);
            const int y0 = std::max(s.y0, by), y1 = std::min(s.y1, by + kTile - 1);
            for (int y = y0; y <= y1; ++y) {
                const double py = y + 0.5;
                for (int x = x0; x <= x1; ++x) {
                    const double px = x + 0.5;
                    double w[3];
                    bool inside = true;
                    for (int e = 0; e < 3 && inside; ++e) {
                        const int a = (e + 1) % 3,
                                  c = (e + 2) % 3; // edge a -> c, opposite vertex e
                        const double dx = s.x[c] - s.x[a], dy = s.y[c] - s.y[a];
                        w[e] = dx * (py - s.y[a]) - dy * (px - s.x[a]);
                        inside = w[e] > 0 || (w[e] == 0 && owns_edge(dx, dy));
                    }
                    if (!inside) continue;
                    const double iz =
                        (w[0] * s.iz[0] + w[1] * s.iz[1] + w[2] * s.iz[2]) * s.inv_area;
                    const float depth = float(cam.ortho ? iz : 1.0 / iz);
                    uint32_t bits;
                    std::memcpy(&bits, &depth, 4);
                    const uint64_t key = (uint64_t(bits) << 32) | s.prim;
                    uint64_t& dst = vis[size_t(y) * W + x];
                    if (key < dst) dst = key;
                }
            }
        }
    });
}

} // namespace sheaf
