#include "core/raster/rasterizer.h"

#include "core/base/parallel.h"
#include "core/raster/raster_tri.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sheaf {
namespace {

constexpr int kTile = 32;
// Triangles set up, binned and drawn at once (rasterize).
constexpr size_t kChunk = size_t(1) << 14;

} // namespace

double raster_near(const CameraFrame& cam) {
    // Orthographic views start at the camera plane. Perspective ones just in front of the eye:
    // nothing nearer than its own float precision (1e-7 of its distance from the origin) is
    // told apart from it, and each triangle's set-up keeps its own precision too (raster_tri.h).
    return cam.ortho ? 0.0 : std::max(1e-30, 1e-7 * length(cam.origin));
}

void rasterize(const PreparedScene& scene, const CameraFrame& cam, std::vector<uint64_t>& vis) {
    vis.resize(size_t(cam.width) * size_t(cam.height));
    rasterize(scene, cam, vis.data());
}

void rasterize(const PreparedScene& scene, const CameraFrame& cam, uint64_t* vis) {
    rasterize(scene, cam, SampleWindow{cam.width, 0, 0, cam.width, cam.height}, vis);
}

void rasterize(const PreparedScene& scene, const CameraFrame& cam, const SampleWindow& win,
               uint64_t* vis) {
    const int W = win.width, H = win.height;
    std::fill_n(vis, win.count(), kEmptyPixel);
    const size_t n = scene.triangle_count(); // analytic primitives are ray-cast by the caller
    if (n == 0) return;

    const double near = raster_near(cam);

    // The triangles go in chunks of kChunk: each chunk is set up, binned and drawn before the
    // next, so the set-up records (104 bytes each, two a triangle) take 3.4 MiB, not 208
    // bytes a triangle of the whole scene. A pixel keeps the least key of all, whatever the
    // order, so the chunks change no pixel.
    const int tx = (W + kTile - 1) / kTile, ty = (H + kTile - 1) / kTile;
    std::vector<ScreenTri> tris;
    std::vector<std::vector<uint32_t>> bins(size_t(tx) * ty);
    for (size_t c0 = 0; c0 < n; c0 += kChunk) {
        const size_t cn = std::min(n - c0, kChunk);
        // 1. Set-up: camera space, near clip, projection, pixel bounds cut to the window. A
        //    clipped quad becomes two triangles.
        tris.resize(2 * cn);
        parallel_for("raster.setup", cn, [&](size_t k) {
            const uint32_t p = uint32_t(c0 + k);
            setup_triangle(scene.tris[p], p, scene.prim_flag(p, kNoImage), cam, near, &tris[2 * k]);
            clip_to_window(tris[2 * k], win);
            clip_to_window(tris[2 * k + 1], win);
        });

        // 2. Binning into screen tiles of the window.
        for (auto& b : bins) b.clear();
        for (uint32_t i = 0; i < tris.size(); ++i) {
            const ScreenTri& s = tris[i];
            if (s.x0 > s.x1 || s.y0 > s.y1) continue;
            for (int by = (s.y0 - win.y) / kTile; by <= (s.y1 - win.y) / kTile; ++by)
                for (int bx = (s.x0 - win.x) / kTile; bx <= (s.x1 - win.x) / kTile; ++bx)
                    bins[size_t(by) * tx + bx].push_back(i);
        }

        // 3. Coverage and depth, one tile per task: no two tasks write the same pixel.
        //    Coverage is tested at the whole grid's pixel, so a window's keys are the whole
        //    frame's.
        parallel_for("raster.tiles", bins.size(), [&](size_t b) {
            const int bx = win.x + int(b % tx) * kTile, by = win.y + int(b / tx) * kTile;
            for (uint32_t i : bins[b]) {
                const ScreenTri& s = tris[i];
                const int x0 = std::max(s.x0, bx), x1 = std::min(s.x1, bx + kTile - 1);
                const int y0 = std::max(s.y0, by), y1 = std::min(s.y1, by + kTile - 1);
                for (int y = y0; y <= y1; ++y)
                    for (int x = x0; x <= x1; ++x) {
                        uint64_t key;
                        if (!cover_pixel(s, x, y, cam.ortho, key)) continue;
                        uint64_t& dst = vis[win.at(x, y)];
                        if (key < dst) dst = key;
                    }
            }
        });
    }
}

} // namespace sheaf
