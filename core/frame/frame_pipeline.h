// The frame pipeline, written once: a wavefront of launches over arrays against the exec seam
// and the tracer seam (seam.h), run by the CPU backend (CpuExec, HostTracer) and the CUDA
// module (CudaExec, WavefrontTracer). Cull units, photons, the scene bound or copied, then
// raster (on a device each set-up triangle's pixel bounds cut into short runs of a row, one
// thread each, a 64-bit atomic minimum of depth | primitive; on host memory the tile
// rasteriser), analytic primary rays, the G-buffer resolve, then per bounce: ray generation
// (count, scan, fill), tracing (the tracer), shading whose sums go into each sample in item
// order (accumulate_in_order), the next wave's hits; finally the box filter and the passes.
// Same images, same statistics on every exec and tracer.
#pragma once

#include "core/base/error.h"
#include "core/base/memory.h"
#include "core/frame/frame.h"
#include "core/frame/frame_stats.h"
#include "core/frame/render_frame.h"
#include "core/frame/scene_copy.h"
#include "core/frame/seam.h"
#include "core/frame/wavefront_tracer.h"
#include "core/raster/raster_tri.h"
#include "core/raster/rasterizer.h"
#include "core/shading/frame_kernels.h"

#include <chrono>
#include <memory>
#include <utility>
#include <vector>

namespace sheaf::wavefront {

/// A wave of surface hits on the executing side.
template <class Exec> struct DeviceHits {
    DeviceBuffer<SurfaceHit, Exec> h;
    size_t n = 0;
    size_t camera = 0; // the first hits, with gather 0; the rest are on gathered paths
};

/// Pixels of one row that one raster thread covers.
constexpr int kCoverRun = 8;

/// The frame, written once: `Exec` runs it (seam.h: the CPU policy, the CUDA policy, the
/// strict test policy), `Tracer` is its intersection stage (HostTracer on the CPU backend,
/// WavefrontTracer, the wavefront of launches, elsewhere).
template <class Exec, class Tracer = WavefrontTracer<Exec>> class FramePipeline {
    static_assert(FrameExec<Exec>, "Exec must provide what core/frame/seam.h lists");
    static_assert(FrameTracer<Tracer, Exec>, "Tracer must provide what core/frame/seam.h lists");

  public:
    /// `keep`: where an exec that outlives its frames keeps the scene's copy between them
    /// (none: the frame copies the scene and frees it at its end).
    FramePipeline(Exec& ex, const PreparedScene& scene, const RenderSettings& s,
                  const ProgressFn& progress, Frame& f, SceneKeep<Exec>* keep = nullptr)
        : ex_(ex), host_(scene), s_(s), progress_(progress), f_(f), st_(f.stats), clock_(ex),
          keep_(keep) {}

    void run() {
        declare_frame_keys(st_);
        const auto start = std::chrono::steady_clock::now();
        const int aa = s_.aa_samples;
        W_ = s_.width * aa, H_ = s_.height * aa;
        const RenderSettings::Rect region = s_.region();
        region_win_ =
            SampleWindow::of_pixels(s_.width, aa, region.x, region.y, region.width, region.height);
        win_ = region_win_;
        const size_t samples = region_win_.count();
        band_rows_ = band_rows();
        cam_ = make_camera_frame(host_.camera, W_, H_, s_.aa_samples);
        last_mark_ = start;
        const std::shared_ptr<const CullUnits> units = cull_units_for(host_, s_);
        mark("cull units");
        // Photons are shot on the host (the same map on every backend, so the same picture)
        // and gathered on the executing side.
        MemoryTracker device_photon_memory; // host memory beside a device's
        MemoryTracker* photon_memory = &device_photon_memory;
        if constexpr (Exec::kHostMemory) {
            // Host memory: the frame's buffers and its photons under one limit.
            limit_memory();
            photon_memory = &ex_.memory();
        } else if (const int64_t available =
                       // Reading the system's free memory takes a tenth of a millisecond:
                       // only with photons.
                   host_.has_photons() ? available_memory_bytes() : 0;
                   available > 0) {
            device_photon_memory.set_limit(available / 10 * 9, available);
        }
        const PhotonMap photons = shoot_photons(host_, *units, s_, st_, *photon_memory);
        mark("photons");
        std::unique_ptr<DeviceScene<Exec>> own;
        CullView cull;
        if constexpr (Exec::kHostMemory) {
            // The executing side reads host memory: the scene is bound, not copied, image
            // textures and their sampler included.
            scene_ = SceneView(host_);
            scene_.photon_map = photons.view();
            cull = host_cull_view(*units);
            mark("bind");
        } else {
            bool reused = false;
            DeviceScene<Exec>& uploaded =
                keep_ ? keep_->scene(ex_, host_, *units, &photons, reused)
                      : *(own = std::make_unique<DeviceScene<Exec>>(ex_, host_, *units, &photons));
            scene_ = uploaded.view;
            cull = uploaded.cull;
            st_.set("device.scene_kept", reused ? 1.0 : 0.0);
            st_.set("device.scene_bytes", double(uploaded.bytes()));
            mark(reused ? "upload (kept)" : "upload");
        }
        params_ = frame_ray_params(host_, s_);
        Tracer tracer(ex_, host_, scene_, *units, cull, s_, st_, clock_);
        tracer_ = &tracer;
        if constexpr (Tracer::kDeviceWork)
            st_.set("device.batch_pairs", double(tracer.batch_pairs()));
        mark("tracer");

        scatter_ = host_.media_scatter_light();
        // Primary visibility of the whole region at once (a rasterised triangle is set up
        // once, not once a band); then the rest of the frame band by band, each band's
        // per-sample buffers and rays freed before the next.
        // A traced projection makes each band's keys with its camera rays: a band's worth.
        const size_t band_samples = size_t(band_rows_) * size_t(region_win_.width);
        DeviceBuffer<uint64_t, Exec> vis(ex_, cam_.traced ? band_samples : samples);
        if (!cam_.traced) rasterize_region(vis.data());
        st_.set("rays.primary", double(samples));
        allocate_pixels();
        mark("visibility");
        const int bands = (region_win_.height + band_rows_ - 1) / band_rows_;
        st_.set("memory.bands", double(bands));
        st_.set("memory.band_samples", double(band_samples));
        for (int b = 0; b < bands; ++b) {
            const int row = b * band_rows_;
            win_ = region_win_;
            win_.y += row;
            win_.height = std::min(band_rows_, region_win_.height - row);
            shade_band(vis.data() + (cam_.traced ? 0 : size_t(row) * size_t(region_win_.width)),
                       row, b, bands);
        }
        win_ = region_win_;
        mark("bands");
        tracer.flush();
        mark("flush");
        download_pixels();
        mark("resolve");
        tracer_ = nullptr;
        clock_.add_to(st_);
        mark("phase times");
        st_.add("time_ms.frame",
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
        frame_totals(st_, host_, s_, ex_.peak_bytes());
        if constexpr (Tracer::kDeviceWork) {
            st_.set("device.launches", double(ex_.launches()));
            st_.set("device.host_waits", double(ex_.host_waits()));
        }
    }

    // Sample rows a band holds: whole pixel rows (a pixel's samples resolve together), about
    // band.samples samples, at least one pixel row.
    int band_rows() const {
        const size_t row = size_t(region_win_.width) * size_t(s_.aa_samples);
        // The rays a camera sample makes, about: a bounce ray and its shadow rays, AO and
        // radiosity's gathers (a light's area samples are lights of their own).
        const size_t rays = 2 + host_.lights.size() + size_t(std::max(0, s_.ao_samples)) +
                            size_t(std::max(0, s_.radiosity_samples));
        const size_t want = s_.band_or(Exec::kHostMemory, region_win_.count(), rays);
        const size_t pixel_rows = std::max<size_t>(1, want / std::max<size_t>(1, row));
        return int(
            std::min<size_t>(pixel_rows * size_t(s_.aa_samples), size_t(region_win_.height)));
    }

    // One band of the region (win_): the camera rays where the projection is traced, the
    // G-buffer from the band's visibility keys, the media along the camera rays, the bounces,
    // and the band's pixels resolved. `row`: the band's first sample row in the region.
    void shade_band(uint64_t* vis, int row, int band, int bands) {
        const size_t n = win_.count();
        radiance_ = DeviceBuffer<Vec3, Exec>(ex_, n);
        tests_ = DeviceBuffer<uint32_t, Exec>(ex_, s_.keeps(kPassTests) ? n : 0);
        fill(ex_, radiance_.data(), n, Vec3(0.0f));
        fill(ex_, tests_.data(), tests_.size(), 0u);
        if (cam_.traced) trace_camera(cam_, vis); // its tests count into the band's samples
        DeviceHits<Exec> hits = gbuffer(vis);
        scatter_light(segments_, n);
        segments_ = DeviceBuffer<MediaSegment, Exec>();
        const float share = 0.9f / float(bands);
        report(0.1f + share * (float(band) + 0.1f));
        for (int bounce = 0; bounce <= s_.trace_depth && hits.n > 0; ++bounce) {
            hits = shade_wave(hits, bounce);
            report(0.1f + share * (float(band) + 0.1f +
                                   0.9f * float(bounce + 1) / float(s_.trace_depth + 1)));
        }
        hits = DeviceHits<Exec>();
        resolve(row);
        radiance_ = DeviceBuffer<Vec3, Exec>();
        tests_ = DeviceBuffer<uint32_t, Exec>();
        depth_ = DeviceBuffer<float, Exec>();
        normal_ = DeviceBuffer<Vec3, Exec>();
        albedo_ = DeviceBuffer<Vec3, Exec>();
        object_ = DeviceBuffer<uint32_t, Exec>();
    }

    /// Host time of the frame's steps in order (cull units, photons, upload, tracer,
    /// visibility, bands, flush, resolve, phase times): where a frame's wall time goes beyond the
    /// device's.
    const std::vector<std::pair<const char*, double>>& host_steps() const { return steps_; }

    // The stages below are public only because nvcc's extended lambdas may not live in private
    // member functions.

    void report(float done) {
        if (progress_ && !progress_(done)) throw RenderError("cancelled");
    }

    // Host memory: a frame too large for the machine is refused before its memory is taken,
    // at once when the per-sample arrays alone would not fit, else when the exec's buffers
    // (rays, keys, hierarchy levels, candidates) would pass what is left. The system would
    // otherwise stop the process (or swap) part way through the frame.
    void limit_memory() {
        const int64_t available = available_memory_bytes();
        if (available <= 0) return; // unknown: no limit
        const int64_t samples = int64_t(region_win_.count());
        const int64_t band = int64_t(band_rows_) * int64_t(region_win_.width);
        // What lives together at a band's primary stage: the region's visibility keys; the
        // band's radiance, tests, depth, normal, albedo, object id, slots and hits (as if
        // every sample hit); the region's passes per pixel.
        const int64_t per_band_sample =
            sizeof(Vec3) * 3 + sizeof(float) + sizeof(uint32_t) * 3 + sizeof(SurfaceHit);
        const int64_t per_pixel = sizeof(float) * (4 + 1 + 3 + 3 + 1 + 1);
        const RenderSettings::Rect region = s_.region();
        const int64_t keys = cam_.traced ? band : samples; // a traced camera's: a band's
        const int64_t fixed = keys * int64_t(sizeof(uint64_t)) + band * per_band_sample +
                              int64_t(region.width) * region.height * per_pixel;
        const int64_t usable = available / 10 * 9; // the rest for what is not counted
        if (fixed > usable)
            throw OutOfMemory("a " + std::to_string(region.width) + "x" +
                              std::to_string(region.height) + " frame with " +
                              std::to_string(s_.aa_samples) + "x" + std::to_string(s_.aa_samples) +
                              " samples per pixel needs at least " + std::to_string(fixed >> 20) +
                              " MiB; this machine has " + std::to_string(available >> 20) +
                              " MiB available");
        ex_.memory().set_limit(usable, available);
    }

    // Projections no plane holds: every sample's camera ray is traced through the ray
    // hierarchy (objects without an image skipped), its closest hit the sample's visibility key.
    void trace_camera(const CameraFrame& cam, uint64_t* vis) {
        const size_t samples = win_.count();
        const SampleWindow win = win_;
        clock_.start("ray_creation");
        fill(ex_, vis, samples, kEmptyPixel);
        DeviceBuffer<uint32_t, Exec> slot_buf(ex_, samples);
        uint32_t* slot = slot_buf.data();
        const SceneView scene = scene_;
        const uint32_t total = count_and_scan(
            ex_, "raygen.count", samples, slot, [=] SHEAF_HD_LAMBDA(size_t i) -> uint32_t {
                Ray r;
                return camera_ray(scene, cam, win.column(i), win.row(i), r) ? 1u : 0u;
            });
        DeviceBatch<Exec> b(ex_, RayType::Camera, total);
        const RaySlots slots = b.slots();
        ex_.launch("raygen.camera", samples, [=] SHEAF_HD_LAMBDA(size_t i) {
            Ray r;
            if (!primary_ray(scene, cam, win.column(i), win.row(i), r)) return;
            slots.rays[slot[i]] = r;
            slots.pixel[slot[i]] = win.global(i);
            slots.weight[slot[i]] = Vec3(1.0f);
        });
        clock_.stop("ray_creation");
        DeviceTraceResult<Exec> r;
        tracer_->trace(b, r);
        count_tests(b, r);
        const uint32_t* pixel = b.pixel.data();
        const uint64_t* closest = r.closest.data();
        ex_.launch("raygen.camera_hits", b.n,
                   [=] SHEAF_HD_LAMBDA(size_t i) { vis[win.local(pixel[i])] = closest[i]; });
    }

    // Primary visibility of the region (win_), for the projections a plane holds: rasterised,
    // the analytic objects merged in, each sample's key in vis.
    void rasterize_region(uint64_t* vis) {
        const CameraFrame cam = cam_;
        const size_t samples = win_.count();
        const SampleWindow win = win_;
        const SceneView scene = scene_;
        clock_.start("raster");
        const size_t tris = host_.triangle_count();
        if constexpr (Exec::kHostMemory) {
            // Binned into screen tiles, one task a tile, no atomics: faster on CPU cores
            // (core/raster/rasterizer.cpp); the same minimum keys.
            rasterize(host_, cam, win, vis);
        } else if (fill(ex_, vis, samples, kEmptyPixel); tris > 0) {
            const double near = raster_near(cam);
            DeviceBuffer<ScreenTri, Exec> screen_buf(ex_, 2 * tris);
            ScreenTri* screen = screen_buf.data();
            ex_.launch("raster.setup", tris, [=] SHEAF_HD_LAMBDA(size_t p) {
                setup_triangle(scene.tris[p], uint32_t(p), scene.prim_flag(uint32_t(p), kNoImage),
                               cam, near, &screen[2 * p]);
                clip_to_window(screen[2 * p], win);
                clip_to_window(screen[2 * p + 1], win);
            });
            // The pixel bounds cut into runs of kCoverRun pixels of a row, one thread
            // each: a triangle as large as the screen is spread over many threads instead
            // of looping over its pixels in one. first[k]: the first run of triangle k.
            const size_t m = 2 * tris;
            DeviceBuffer<uint64_t, Exec> first_buf(ex_, m);
            uint64_t* first = first_buf.data();
            ex_.launch("raster.runs", m, [=] SHEAF_HD_LAMBDA(size_t k) {
                const ScreenTri& s = screen[k];
                first[k] = s.x0 > s.x1 || s.y0 > s.y1
                               ? 0
                               : uint64_t(s.y1 - s.y0 + 1) *
                                     uint64_t((s.x1 - s.x0 + kCoverRun) / kCoverRun);
            });
            const uint64_t runs = ex_.exclusive_scan(first, m);
            ex_.launch("raster.cover", size_t(runs), [=] SHEAF_HD_LAMBDA(size_t j) {
                // The last triangle whose runs start at or before j (never an empty one:
                // an empty triangle's successor starts where it does).
                size_t lo = 0, hi = m;
                while (hi - lo > 1) {
                    const size_t mid = lo + (hi - lo) / 2;
                    (first[mid] <= j ? lo : hi) = mid;
                }
                const ScreenTri& s = screen[lo];
                const uint64_t per_row = uint64_t((s.x1 - s.x0 + kCoverRun) / kCoverRun);
                const uint64_t local = j - first[lo];
                const int y = s.y0 + int(local / per_row);
                const int xa = s.x0 + int(local % per_row) * kCoverRun;
                const int xb = xa + kCoverRun - 1 < s.x1 ? xa + kCoverRun - 1 : s.x1;
                for (int x = xa; x <= xb; ++x) {
                    uint64_t key;
                    if (cover_pixel(s, x, y, cam.ortho, key))
                        atomic_min_u64(&vis[win.at(x, y)], key);
                }
            });
        }
        if (scene.analytic_count > 0)
            ex_.launch("raster.analytic", samples, [=] SHEAF_HD_LAMBDA(size_t i) {
                vis[i] = cast_analytic_pixel(scene, cam, win.column(i), win.row(i), vis[i]);
            });
        clock_.stop("raster");
    }

    // The band's (win_) surface hits and primary passes from its visibility keys.
    DeviceHits<Exec> gbuffer(const uint64_t* vis) {
        const CameraFrame cam = cam_;
        const size_t samples = win_.count();
        const int W = W_;
        const SampleWindow win = win_;
        const SceneView scene = scene_;
        clock_.start("gbuffer");
        DeviceBuffer<uint32_t, Exec> slot_buf(ex_, samples);
        uint32_t* slot = slot_buf.data();
        const uint32_t count = count_and_scan(
            ex_, "gbuffer.count", samples, slot,
            [=] SHEAF_HD_LAMBDA(size_t i) -> uint32_t { return vis[i] != kEmptyPixel ? 1u : 0u; });
        DeviceHits<Exec> hits;
        hits.h = DeviceBuffer<SurfaceHit, Exec>(ex_, count);
        hits.n = hits.camera = count;
        // Only the passes the frame keeps.
        auto kept = [&](PassBit bit) { return s_.keeps(bit) ? samples : size_t(0); };
        depth_ = DeviceBuffer<float, Exec>(ex_, kept(kPassDepth));
        normal_ = DeviceBuffer<Vec3, Exec>(ex_, kept(kPassNormal));
        albedo_ = DeviceBuffer<Vec3, Exec>(ex_, kept(kPassAlbedo));
        object_ = DeviceBuffer<uint32_t, Exec>(ex_, kept(kPassObjectId));
        SurfaceHit* out = hits.h.data();
        Vec3* radiance = radiance_.data();
        float* depth = depth_.data();
        Vec3* normal = normal_.data();
        Vec3* albedo = albedo_.data();
        uint32_t* object = object_.data();
        if (scatter_) segments_ = DeviceBuffer<MediaSegment, Exec>(ex_, samples);
        MediaSegment* segment = segments_.data();
        ex_.launch("gbuffer.resolve", samples, [=] SHEAF_HD_LAMBDA(size_t i) {
            const PrimarySample ps = primary_sample(scene, cam, W, win.global(i), vis[i]);
            radiance[i] = ps.radiance;
            if (depth) depth[i] = ps.depth;
            if (normal) normal[i] = ps.normal;
            if (albedo) albedo[i] = ps.albedo;
            if (object) object[i] = ps.object;
            if (segment) segment[i] = ps.segment;
            if (ps.hit) out[slot[i]] = ps.h;
        });
        clock_.stop("gbuffer");
        return hits;
    }

    // Shadow and AO rays, traced and added; returns the hits of the reflection, refraction and
    // radiosity gather rays (in that order, each in ray order).
    DeviceHits<Exec> shade_wave(const DeviceHits<Exec>& hits, int bounce) {
        const bool trace_ao = bounce == 0 && s_.ao_samples > 0;
        const SceneView scene = scene_;
        const RayGenParams params = params_;
        const SurfaceHit* h = hits.h.data();
        const size_t n = hits.n;
        Vec3* radiance = radiance_.data();
        const SampleWindow win = win_;

        {
            // Shadow and AO rays, freed before the bounce rays are made.
            DeviceBatch<Exec> shadow = shadow_rays(hits);
            DeviceBatch<Exec> ao(ex_, RayType::Ao, 0);
            if (trace_ao) ao = ao_rays(hits);
            {
                // Terms that need no ray: emission, ambient (unless AO traces it), shadowless
                // lights.
                clock_.start("shading");
                accumulate_in_order(
                    ex_, n, radiance,
                    [=] SHEAF_HD_LAMBDA(size_t i) -> uint32_t { return win.local(h[i].pixel); },
                    [=] SHEAF_HD_LAMBDA(size_t i, Vec3 & v) -> bool {
                        v = unshadowed_terms(scene, h[i], trace_ao, params);
                        return true;
                    });
                clock_.stop("shading");
            }
            DeviceTraceResult<Exec> r;
            tracer_->trace(shadow, r);
            add_unoccluded(shadow, r);
            if (trace_ao) {
                tracer_->trace(ao, r);
                add_unoccluded(ao, r);
            }
        }
        if (bounce >= s_.trace_depth) return DeviceHits<Exec>();

        DeviceBuffer<BounceSplit, Exec> split_buf(ex_, n);
        BounceSplit* split = split_buf.data();
        DeviceBatch<Exec> refl(ex_, RayType::Reflection, 0), refr(ex_, RayType::Refraction, 0);
        {
            clock_.start("ray_creation");
            ex_.launch("raygen.split", n,
                       [=] SHEAF_HD_LAMBDA(size_t i) { split[i] = bounce_split(scene, h[i]); });
            refl = bounce_rays(hits, split, RayType::Reflection);
            refr = bounce_rays(hits, split, RayType::Refraction);
            clock_.stop("ray_creation");
        }
        const bool radiosity = params_.radiosity_samples > 0;
        DeviceBatch<Exec> diffuse(ex_, RayType::Diffuse, 0);
        if (radiosity) diffuse = diffuse_rays(hits);
        DeviceHits<Exec> next;
        next.h = DeviceBuffer<SurfaceHit, Exec>(ex_, refl.n + refr.n + diffuse.n);
        next_hits(refl, next);
        next_hits(refr, next);
        next.camera = next.n;
        if (radiosity) next_hits(diffuse, next);
        return next;
    }

    DeviceBatch<Exec> diffuse_rays(const DeviceHits<Exec>& hits) {
        clock_.start("ray_creation");
        const SceneView scene = scene_;
        const RayGenParams params = params_;
        const SurfaceHit* h = hits.h.data();
        check_batch_bound(uint64_t(hits.n) * uint64_t(params_.radiosity_samples), RayType::Diffuse);
        DeviceBuffer<uint32_t, Exec> count_buf(ex_, hits.n), offset_buf(ex_, hits.n);
        uint32_t* count = count_buf.data();
        uint32_t* offset = offset_buf.data();
        ex_.launch("raygen.diffuse_count", hits.n, [=] SHEAF_HD_LAMBDA(size_t i) {
            count[i] = diffuse_ray_count(scene, h[i], params);
        });
        const uint32_t total =
            count_and_scan(ex_, "raygen.count", hits.n, offset,
                           [=] SHEAF_HD_LAMBDA(size_t i) -> uint32_t { return count[i]; });
        DeviceBatch<Exec> out(ex_, RayType::Diffuse, total);
        const RaySlots slots = out.slots();
        ex_.launch("raygen.fill", hits.n, [=] SHEAF_HD_LAMBDA(size_t i) {
            diffuse_ray_fill(scene, h[i], count[i], offset[i], params, slots);
        });
        clock_.stop("ray_creation");
        return out;
    }

    DeviceBatch<Exec> shadow_rays(const DeviceHits<Exec>& hits) {
        clock_.start("ray_creation");
        const SceneView scene = scene_;
        const RayGenParams params = params_;
        const SurfaceHit* h = hits.h.data();
        ShadowLayout layout;
        layout.hits = hits.n, layout.camera = hits.camera;
        layout.lights = uint32_t(host_.lights.size());
        const size_t k = layout.elements();
        check_batch_bound(k, RayType::Shadow);
        DeviceBuffer<uint32_t, Exec> offset_buf(ex_, k);
        uint32_t* offset = offset_buf.data();
        const uint32_t total = count_and_scan(
            ex_, "raygen.count", k, offset, [=] SHEAF_HD_LAMBDA(size_t i) -> uint32_t {
                return shadow_ray_count(scene, h, layout, i, params);
            });
        DeviceBatch<Exec> out(ex_, RayType::Shadow, total);
        const RaySlots slots = out.slots();
        ex_.launch("raygen.fill", k, [=] SHEAF_HD_LAMBDA(size_t i) {
            shadow_ray_fill(scene, h, layout, i, offset[i], params, slots);
        });
        clock_.stop("ray_creation");
        return out;
    }

    DeviceBatch<Exec> ao_rays(const DeviceHits<Exec>& hits) {
        clock_.start("ray_creation");
        const SceneView scene = scene_;
        const RayGenParams params = params_;
        const SurfaceHit* h = hits.h.data();
        const uint32_t per = uint32_t(params_.ao_samples);
        check_batch_bound(uint64_t(hits.n) * per, RayType::Ao);
        DeviceBatch<Exec> out(ex_, RayType::Ao, hits.n * per);
        const RaySlots slots = out.slots();
        ex_.launch("raygen.ao", hits.n, [=] SHEAF_HD_LAMBDA(size_t i) {
            ao_ray_fill(scene, h[i], uint32_t(i) * per, params, slots);
        });
        clock_.stop("ray_creation");
        return out;
    }

    DeviceBatch<Exec> bounce_rays(const DeviceHits<Exec>& hits, const BounceSplit* split,
                                  RayType type) {
        const RayGenParams params = params_;
        const SurfaceHit* h = hits.h.data();
        const bool reflection = type == RayType::Reflection;
        DeviceBuffer<uint32_t, Exec> offset_buf(ex_, hits.n);
        uint32_t* offset = offset_buf.data();
        const uint32_t total = count_and_scan(
            ex_, "raygen.count", hits.n, offset, [=] SHEAF_HD_LAMBDA(size_t i) -> uint32_t {
                return reflection ? reflect_ray_count(split[i], params)
                                  : refract_ray_count(split[i], params);
            });
        DeviceBatch<Exec> out(ex_, type, total);
        const RaySlots slots = out.slots();
        ex_.launch("raygen.fill", hits.n, [=] SHEAF_HD_LAMBDA(size_t i) {
            if (reflection)
                reflect_ray_fill(h[i], split[i], offset[i], params, slots);
            else
                refract_ray_fill(h[i], split[i], offset[i], params, slots);
        });
        return out;
    }

    // Shadow and AO rays that reach their end add their radiance (through what transparent
    // surfaces let pass), in ray order per sample; every ray's tests go to its sample.
    void add_unoccluded(const DeviceBatch<Exec>& b, const DeviceTraceResult<Exec>& r) {
        clock_.start("shading");
        const uint32_t* pixel = b.pixel.data();
        const Vec3* weight = b.weight.data();
        const uint8_t* occluded = r.occluded.data();
        const uint64_t* pass_log = r.pass_log.data();
        const SampleWindow win = win_;
        accumulate_in_order(
            ex_, b.n, radiance_.data(),
            [=] SHEAF_HD_LAMBDA(size_t i) -> uint32_t { return win.local(pixel[i]); },
            [=] SHEAF_HD_LAMBDA(size_t i, Vec3 & v) -> bool {
                if (occluded[i]) return false;
                v = pass_log ? weight[i] * pass_from_logs(&pass_log[3 * i]) : weight[i];
                return true;
            });
        count_tests(b, r);
        clock_.stop("shading");
    }

    // The light the media along the n segments scatter from the lights that cast shadows:
    // their shadow rays (core/shading/media_light.h), traced in batches of consecutive
    // segments as the CPU backend always has.
    void scatter_light(const DeviceBuffer<MediaSegment, Exec>& segments, size_t n) {
        if (!scatter_) return;
        const SceneView scene = scene_;
        const RayGenParams params = params_;
        const size_t per = media_segments_per_batch(host_);
        for (size_t first = 0; first < n; first += per) {
            const size_t count = n - first < per ? n - first : per;
            const MediaSegment* seg = segments.data() + first;
            clock_.start("ray_creation");
            DeviceBuffer<uint32_t, Exec> offset_buf(ex_, count);
            uint32_t* offset = offset_buf.data();
            const uint32_t total =
                count_and_scan(ex_, "raygen.media_count", count, offset,
                               [=] SHEAF_HD_LAMBDA(size_t i) -> uint32_t {
                                   return media_light_count(scene, seg[i], params);
                               });
            DeviceBatch<Exec> b(ex_, RayType::Shadow, total);
            const RaySlots slots = b.slots();
            ex_.launch("raygen.media_fill", count, [=] SHEAF_HD_LAMBDA(size_t i) {
                media_light_fill(scene, seg[i], offset[i], params, slots);
            });
            clock_.stop("ray_creation");
            if (total == 0) continue;
            DeviceTraceResult<Exec> r;
            tracer_->trace(b, r);
            add_unoccluded(b, r);
        }
    }

    void count_tests(const DeviceBatch<Exec>& b, const DeviceTraceResult<Exec>& r) {
        if (!s_.keeps(kPassTests)) return; // the samples' counts feed the tests pass only
        const uint32_t* pixel = b.pixel.data();
        const uint32_t* tests = r.tests.data();
        uint32_t* sample_tests = tests_.data();
        const SampleWindow win = win_;
        ex_.launch("shade.tests", b.n, [=] SHEAF_HD_LAMBDA(size_t i) {
            atomic_add_u32(&sample_tests[win.local(pixel[i])], tests[i]);
        });
    }

    // Traces a reflection, refraction or gather batch: misses bring the sky, hits become surface
    // points of the next wave, appended to `next` in ray order, with the fog on their way.
    void next_hits(const DeviceBatch<Exec>& b, DeviceHits<Exec>& next) {
        DeviceTraceResult<Exec> r;
        tracer_->trace(b, r);
        clock_.start("shading");
        count_tests(b, r);
        const SceneView scene = scene_;
        const Ray* rays = b.rays.data();
        const uint32_t* pixel = b.pixel.data();
        const Vec3* weight = b.weight.data();
        const uint64_t* closest = r.closest.data();
        const SampleWindow win = win_;
        accumulate_in_order(
            ex_, b.n, radiance_.data(),
            [=] SHEAF_HD_LAMBDA(size_t i) -> uint32_t { return win.local(pixel[i]); },
            [=] SHEAF_HD_LAMBDA(size_t i, Vec3 & v) -> bool {
                if (closest[i] != kNoHit) return false;
                v = leave_scene(scene, rays[i].origin, rays[i].dir, weight[i], pixel[i]);
                return true;
            });
        DeviceBuffer<uint32_t, Exec> slot_buf(ex_, b.n);
        uint32_t* slot = slot_buf.data();
        const uint32_t count = count_and_scan(
            ex_, "shade.count", b.n, slot,
            [=] SHEAF_HD_LAMBDA(size_t i) -> uint32_t { return closest[i] != kNoHit ? 1u : 0u; });
        DeviceBuffer<Vec3, Exec> fog_buf(ex_, count);
        Vec3* fog = fog_buf.data();
        SurfaceHit* out = next.h.data() + next.n;
        const uint32_t* tag = b.type == RayType::Diffuse ? b.light.data() : nullptr;
        // Radiosity's gather rays leave media out of their scattering, as POV-Ray's radiosity
        // does unless told `media on`.
        DeviceBuffer<MediaSegment, Exec> segments;
        if (scatter_ && b.type != RayType::Diffuse)
            segments = DeviceBuffer<MediaSegment, Exec>(ex_, b.n);
        MediaSegment* segment = segments.data();
        ex_.launch("shade.next", b.n, [=] SHEAF_HD_LAMBDA(size_t i) {
            if (closest[i] == kNoHit) {
                if (segment)
                    segment[i] = media_segment(scene, rays[i].origin, rays[i].dir, INFINITY,
                                               weight[i], pixel[i]);
                return;
            }
            out[slot[i]] = bounce_hit(scene, rays[i], closest[i], pixel[i], weight[i], fog[slot[i]],
                                      segment ? &segment[i] : nullptr);
            if (tag) out[slot[i]].gather = tag[i];
        });
        if (host_.lights_the_way()) // in ray order: the same sums on every accel
            accumulate_in_order(
                ex_, count, radiance_.data(),
                [=] SHEAF_HD_LAMBDA(size_t k) -> uint32_t { return win.local(out[k].pixel); },
                [=] SHEAF_HD_LAMBDA(size_t k, Vec3 & v) -> bool {
                    v = fog[k];
                    return true;
                });
        next.n += count;
        clock_.stop("shading");
        scatter_light(segments, b.n);
    }

    // The region's kept passes, one element a pixel (output.passes): on host memory the
    // frame's own arrays, which the bands resolve into; on a device buffers read back at the
    // end.
    void allocate_pixels() {
        const RenderSettings::Rect region = s_.region();
        const size_t pixels = size_t(region.width) * size_t(region.height);
        auto kept = [&](PassBit bit, size_t n) { return s_.keeps(bit) ? n : size_t(0); };
        f_.width = region.width, f_.height = region.height;
        f_.x = region.x, f_.y = region.y;
        f_.full_width = s_.width, f_.full_height = s_.height;
        if constexpr (Exec::kHostMemory) {
            f_.rgba = host_vector<float>(kept(kPassCombined, 4 * pixels));
            f_.depth = host_vector<float>(kept(kPassDepth, pixels));
            f_.normal = host_vector<Vec3>(kept(kPassNormal, pixels));
            f_.albedo = host_vector<Vec3>(kept(kPassAlbedo, pixels));
            f_.object_id = host_vector<uint32_t>(kept(kPassObjectId, pixels));
            f_.tests = host_vector<uint32_t>(kept(kPassTests, pixels));
            pixels_ = {f_.rgba.data(),   f_.depth.data(),     f_.normal.data(),
                       f_.albedo.data(), f_.object_id.data(), f_.tests.data()};
        } else {
            rgba_ = DeviceBuffer<float, Exec>(ex_, kept(kPassCombined, 4 * pixels));
            depth_pixels_ = DeviceBuffer<float, Exec>(ex_, kept(kPassDepth, pixels));
            normal_pixels_ = DeviceBuffer<Vec3, Exec>(ex_, kept(kPassNormal, pixels));
            albedo_pixels_ = DeviceBuffer<Vec3, Exec>(ex_, kept(kPassAlbedo, pixels));
            object_pixels_ = DeviceBuffer<uint32_t, Exec>(ex_, kept(kPassObjectId, pixels));
            tests_pixels_ = DeviceBuffer<uint32_t, Exec>(ex_, kept(kPassTests, pixels));
            pixels_ = {rgba_.data(),          depth_pixels_.data(),  normal_pixels_.data(),
                       albedo_pixels_.data(), object_pixels_.data(), tests_pixels_.data()};
        }
    }

    // Box filter of the aa x aa samples of each pixel of the band (win_, from sample row `row`
    // of the region); passes from the centre sample.
    void resolve(int row) {
        clock_.start("shading");
        const int aa = s_.aa_samples, w = win_.width / aa, W = win_.width;
        const float gamma = scene_.working_gamma;
        const size_t first = size_t(row / aa) * size_t(w); // the band's first pixel
        const size_t pixels = size_t(w) * size_t(win_.height / aa);
        const SampleBuffers in{radiance_.data(), tests_.data(),  depth_.data(),
                               normal_.data(),   albedo_.data(), object_.data()};
        auto at = [first](auto* p, size_t per) { return p ? p + first * per : p; };
        const PixelBuffers out{at(pixels_.rgba, 4),   at(pixels_.depth, 1),  at(pixels_.normal, 1),
                               at(pixels_.albedo, 1), at(pixels_.object, 1), at(pixels_.tests, 1)};
        ex_.launch("resolve", pixels,
                   [=] SHEAF_HD_LAMBDA(size_t p) { resolve_pixel(p, w, aa, W, gamma, in, out); });
        clock_.stop("shading");
    }

    // A device's passes, read back to the frame.
    void download_pixels() {
        if constexpr (!Exec::kHostMemory) {
            clock_.start("shading");
            f_.rgba = rgba_.download();
            f_.depth = depth_pixels_.download();
            f_.normal = normal_pixels_.download();
            f_.albedo = albedo_pixels_.download();
            f_.object_id = object_pixels_.download();
            f_.tests = tests_pixels_.download();
            clock_.stop("shading");
        }
    }

  private:
    Exec& ex_;
    const PreparedScene& host_;
    const RenderSettings& s_;
    const ProgressFn& progress_;
    Frame& f_;
    Stats& st_;
    PhaseClock<Exec> clock_;
    SceneKeep<Exec>* keep_ = nullptr;
    SceneView scene_;
    Tracer* tracer_ = nullptr;
    RayGenParams params_;
    int W_ = 0, H_ = 0;       // the whole frame's sample grid
    SampleWindow region_win_; // the region's part of it
    SampleWindow win_;        // the band of the region the per-sample buffers hold
    int band_rows_ = 0;       // sample rows of a band (the last may have fewer)
    CameraFrame cam_;
    PixelBuffers pixels_{};                         // the region's kept passes
    DeviceBuffer<float, Exec> rgba_, depth_pixels_; // a device's passes, until read back
    DeviceBuffer<Vec3, Exec> normal_pixels_, albedo_pixels_;
    DeviceBuffer<uint32_t, Exec> object_pixels_, tests_pixels_;
    DeviceBuffer<Vec3, Exec> radiance_;
    DeviceBuffer<uint32_t, Exec> tests_;
    DeviceBuffer<float, Exec> depth_;
    DeviceBuffer<Vec3, Exec> normal_, albedo_;
    DeviceBuffer<uint32_t, Exec> object_;
    std::chrono::steady_clock::time_point last_mark_;
    std::vector<std::pair<const char*, double>> steps_;
    void mark(const char* step) {
        const auto now = std::chrono::steady_clock::now();
        steps_.emplace_back(step,
                            std::chrono::duration<double, std::milli>(now - last_mark_).count());
        last_mark_ = now;
    }
    bool scatter_ = false;                      // media scatter the lights that cast shadows
    DeviceBuffer<MediaSegment, Exec> segments_; // the camera rays' ways, for scatter_light
};

} // namespace sheaf::wavefront
