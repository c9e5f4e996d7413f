#include "core/render/renderer.h"

#include "core/base/error.h"
#include "core/base/parallel.h"
#include "core/base/timer.h"
#include "core/raster/rasterizer.h"
#include "core/rays/ray_gen.h"
#include "core/render/frame_kernels.h"
#include "core/render/frame_stats.h"
#include "core/render/media_light.h"
#include "core/render/photon_pass.h"
#include "core/rsh/trace.h"
#include "core/sort/radix_sort.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

namespace sheaf {
namespace {

class FramePipeline {
  public:
    FramePipeline(const PreparedScene& scene, const RenderSettings& s, const ProgressFn& progress,
                  Frame& f)
        : scene_(scene), s_(s), progress_(progress), f_(f), st_(f.stats) {}

    void run() {
        declare_frame_keys(st_);
        PhaseTimer frame_timer(st_, "time_ms.frame");
        const int aa = s_.aa_samples;
        W_ = s_.width * aa, H_ = s_.height * aa;
        limit_memory();
        radiance_.assign(size_t(W_) * H_, Vec3(0.0f));
        tests_.assign(size_t(W_) * H_, 0);
        memory_.add(int64_t(radiance_.size() * sizeof(Vec3)));
        params_ = frame_ray_params(scene_, s_);
        units_ = cull_units_for(scene_, s_);
        photons_ = shoot_photons(scene_, *units_, s_, st_, memory_);
        view_.photon_map = photons_.view();

        scatter_ = scene_.media_scatter_light();
        std::vector<SurfaceHit> hits = primary();
        scatter_light(segments_);
        release_segments();
        report(0.1f);
        for (int bounce = 0; bounce <= s_.trace_depth && !hits.empty(); ++bounce) {
            hits = shade_wave(hits, bounce);
            report(0.1f + 0.9f * float(bounce + 1) / float(s_.trace_depth + 1));
        }
        memory_.sub(hit_bytes_);
        hit_bytes_ = 0;
        resolve();
        frame_timer.stop();
        frame_totals(st_, scene_, s_, memory_.peak());
    }

  private:
    // A frame too large for the machine is refused before its memory is taken: at once when
    // the per-sample arrays alone would not fit, else when the tracked buffers (rays, keys,
    // hierarchy levels, candidates) would pass what is left. The system would otherwise stop
    // the process (or swap) part way through the frame.
    void limit_memory() {
        const int64_t available = available_memory_bytes();
        if (available <= 0) return; // unknown: no limit
        const int64_t samples = int64_t(W_) * H_;
        // Untracked arrays that live together in primary(): radiance, tests, depth, normal,
        // albedo, object id, the visibility buffer and its slots, the hits (as if every
        // sample hit); the frame's passes per pixel.
        const int64_t per_sample = sizeof(Vec3) * 3 + sizeof(float) + sizeof(uint32_t) * 3 +
                                   sizeof(uint64_t) + sizeof(SurfaceHit);
        const int64_t per_pixel = sizeof(float) * (4 + 1 + 3 + 3 + 1 + 1);
        const int64_t fixed = samples * per_sample + int64_t(s_.width) * s_.height * per_pixel;
        const int64_t usable = available / 10 * 9; // the rest for what is not counted
        if (fixed > usable)
            throw OutOfMemory("a " + std::to_string(s_.width) + "x" + std::to_string(s_.height) +
                              " frame with " + std::to_string(s_.aa_samples) + "x" +
                              std::to_string(s_.aa_samples) + " samples per pixel needs at least " +
                              std::to_string(fixed >> 20) + " MiB; this machine has " +
                              std::to_string(available >> 20) + " MiB available");
        memory_.set_limit(usable - fixed, available);
    }

    void report(float done) {
        if (progress_ && !progress_(done)) throw RenderError("cancelled");
    }

    // Analytic objects are ray-cast at the pixel centres and merged into the visibility buffer
    // by the same depth key as the rasterised triangles.
    void cast_analytic(const CameraFrame& cam, std::vector<uint64_t>& vis) {
        if (view_.analytic_count == 0) return;
        parallel_for(
            "raster.analytic", vis.size(),
            [&](size_t i) { vis[i] = cast_analytic_pixel(view_, cam, int(i % W_), int(i / W_), vis[i]); },
            256);
    }

    // Projections no plane holds: every sample's camera ray is traced like a reflection ray
    // (through the ray hierarchy, objects without an image skipped), and its closest hit
    // becomes the sample's visibility key.
    void trace_camera(const CameraFrame& cam, std::vector<uint64_t>& vis) {
        vis.assign(size_t(W_) * H_, kEmptyPixel);
        RayBatch b(RayType::Camera, memory_);
        {
            // Count, scan, fill (the wavefront's order): a ray for every sample that has one.
            PhaseTimer t(st_, "time_ms.ray_creation");
            std::vector<uint32_t> slot(vis.size());
            parallel_for(
                "camera.count", vis.size(),
                [&](size_t i) {
                    Ray r;
                    slot[i] = camera_ray(view_, cam, int(i % W_), int(i / W_), r) ? 1u : 0u;
                },
                1024);
            uint32_t count = 0;
            for (uint32_t& s : slot) {
                const uint32_t has = s;
                s = count, count += has;
            }
            b.resize(count);
            parallel_for(
                "camera.fill", vis.size(),
                [&](size_t i) {
                    Ray r;
                    if (!primary_ray(view_, cam, int(i % W_), int(i / W_), r)) return;
                    b.rays[slot[i]] = r;
                    b.pixel[slot[i]] = uint32_t(i);
                    b.weight[slot[i]] = Vec3(1.0f);
                },
                1024);
        }
        TraceResult r;
        trace_batch(scene_, *units_, b, s_, st_, memory_, r);
        count_tests(b, r);
        for (size_t i = 0; i < b.size(); ++i) vis[b.pixel[i]] = r.closest[i];
    }

    // Primary visibility (rasterised, or traced for the projections that need it), resolved to
    // surface hits and the primary passes.
    std::vector<SurfaceHit> primary() {
        const CameraFrame cam = make_camera_frame(scene_.camera, W_, H_, s_.aa_samples);
        std::vector<uint64_t> vis;
        if (cam.traced) {
            trace_camera(cam, vis);
        } else {
            PhaseTimer t(st_, "time_ms.raster");
            rasterize(scene_, cam, vis);
            cast_analytic(cam, vis);
        }
        memory_.add(int64_t(vis.size() * sizeof(uint64_t)));
        st_.set("rays.primary", double(vis.size()));
        PhaseTimer t(st_, "time_ms.gbuffer");
        std::vector<uint32_t> slot(vis.size());
        uint32_t count = 0;
        for (size_t i = 0; i < vis.size(); ++i) {
            slot[i] = count;
            count += vis[i] != kEmptyPixel ? 1 : 0;
        }
        std::vector<SurfaceHit> hits(count);
        depth_.assign(vis.size(), INFINITY);
        normal_.assign(vis.size(), Vec3(0.0f));
        albedo_.assign(vis.size(), Vec3(0.0f));
        object_.assign(vis.size(), 0xFFFFFFFFu);
        if (scatter_) take_segments(vis.size());
        parallel_for(
            "gbuffer.resolve", vis.size(),
            [&](size_t i) {
                const PrimarySample ps = primary_sample(view_, cam, W_, i, vis[i]);
                radiance_[i] = ps.radiance;
                if (!ps.hit) return;
                hits[slot[i]] = ps.h;
                depth_[i] = ps.depth;
                normal_[i] = ps.normal;
                albedo_[i] = ps.albedo;
                object_[i] = ps.object;
                if (scatter_) segments_[i] = ps.segment;
            },
            1024);
        memory_.sub(int64_t(vis.size() * sizeof(uint64_t)));
        return hits;
    }

    void accumulate(const RayBatch& batch, const TraceResult& r) {
        // In ray order, one thread: the sums, and so the image, are the same on every accel.
        const bool filtered = !r.pass_log.empty();
        for (size_t i = 0; i < batch.size(); ++i)
            if (!r.occluded[i])
                radiance_[batch.pixel[i]] += filtered ? batch.weight[i] * r.pass(i) : batch.weight[i];
    }

    void count_tests(const RayBatch& batch, const TraceResult& r) {
        for (size_t i = 0; i < batch.size(); ++i) tests_[batch.pixel[i]] += r.tests[i];
    }

    // Room for n media segments, counted by the memory guard until release_segments.
    void take_segments(size_t n) {
        release_segments();
        memory_.add(int64_t(n * sizeof(MediaSegment)));
        segments_.assign(n, MediaSegment());
    }
    void release_segments() {
        memory_.sub(int64_t(segments_.size() * sizeof(MediaSegment)));
        segments_.clear();
        segments_.shrink_to_fit();
    }

    // The light the media along `segs` scatter from the lights that cast shadows: their
    // shadow rays (core/render/media_light.h), traced in batches of consecutive segments.
    void scatter_light(const std::vector<MediaSegment>& segs) {
        if (!scatter_) return;
        const size_t per = media_segments_per_batch(scene_);
        for (size_t first = 0; first < segs.size(); first += per) {
            const size_t n = std::min(per, segs.size() - first);
            const MediaSegment* seg = segs.data() + first;
            RayBatch b(RayType::Shadow, memory_);
            {
                PhaseTimer t(st_, "time_ms.ray_creation");
                std::vector<uint32_t> offset(n);
                parallel_for(
                    "raygen.media_count", n,
                    [&](size_t i) { offset[i] = media_light_count(view_, seg[i], params_); }, 256);
                uint64_t most = 0;
                for (uint32_t c : offset) most += c;
                check_batch_bound(most, RayType::Shadow);
                b.resize(exclusive_scan_inplace(offset));
                const RaySlots slots{b.rays.data(), b.pixel.data(), b.weight.data(),
                                     b.light.data()};
                parallel_for(
                    "raygen.media_fill", n,
                    [&](size_t i) { media_light_fill(view_, seg[i], offset[i], params_, slots); },
                    256);
            }
            if (b.size() == 0) continue;
            TraceResult r;
            trace_batch(scene_, *units_, b, s_, st_, memory_, r);
            PhaseTimer t(st_, "time_ms.shading");
            accumulate(b, r);
            count_tests(b, r);
        }
    }

    // Shades one wave of hits; returns the hits of its reflection, refraction and radiosity
    // gather rays, in that order.
    std::vector<SurfaceHit> shade_wave(const std::vector<SurfaceHit>& hits, int bounce) {
        RayBatch shadow(RayType::Shadow, memory_), ao(RayType::Ao, memory_);
        const bool trace_ao = bounce == 0 && s_.ao_samples > 0;
        {
            PhaseTimer t(st_, "time_ms.ray_creation");
            generate_shadow_rays(view_, hits, params_, shadow);
            if (trace_ao) generate_ao_rays(view_, hits, params_, ao);
        }
        {
            // Terms that need no ray: emission, ambient (unless AO traces it), the photons'
            // light, shadowless lights. Computed in parallel (a photon search is not cheap),
            // added in order.
            PhaseTimer t(st_, "time_ms.shading");
            std::vector<Vec3> terms(hits.size());
            parallel_for(
                "shade.unshadowed", hits.size(),
                [&](size_t i) { terms[i] = unshadowed_terms(view_, hits[i], trace_ao, params_); },
                256);
            for (size_t i = 0; i < hits.size(); ++i) radiance_[hits[i].pixel] += terms[i];
        }
        TraceResult r;
        trace_batch(scene_, *units_, shadow, s_, st_, memory_, r);
        {
            PhaseTimer t(st_, "time_ms.shading");
            accumulate(shadow, r);
            count_tests(shadow, r);
        }
        if (trace_ao) {
            trace_batch(scene_, *units_, ao, s_, st_, memory_, r);
            PhaseTimer t(st_, "time_ms.shading");
            accumulate(ao, r);
            count_tests(ao, r);
        }
        if (bounce >= s_.trace_depth) return {};

        RayBatch refl(RayType::Reflection, memory_), refr(RayType::Refraction, memory_);
        RayBatch diffuse(RayType::Diffuse, memory_);
        {
            PhaseTimer t(st_, "time_ms.ray_creation");
            generate_bounce_rays(view_, hits, params_, refl, refr);
            generate_diffuse_rays(view_, hits, params_, diffuse);
        }
        std::vector<SurfaceHit> next;
        int64_t gathered_bytes = 0; // the gathered points among them, which the memory guard counts
        for (RayBatch* b : {&refl, &refr, &diffuse}) {
            if (b == &diffuse && params_.radiosity_samples == 0) continue;
            trace_batch(scene_, *units_, *b, s_, st_, memory_, r);
            PhaseTimer t(st_, "time_ms.shading");
            count_tests(*b, r);
            std::vector<uint32_t> slot(b->size());
            // Radiosity's gather rays leave media out of their scattering, as POV-Ray's
            // radiosity does unless told `media on`.
            const bool segments = scatter_ && b != &diffuse;
            if (segments) take_segments(b->size());
            uint32_t count = 0;
            for (size_t i = 0; i < b->size(); ++i) {
                slot[i] = count;
                if (r.closest[i] != kNoHit) {
                    ++count;
                    continue;
                }
                const Ray& ray = b->rays[i];
                radiance_[b->pixel[i]] +=
                    leave_scene(view_, ray.origin, ray.dir, b->weight[i], b->pixel[i]);
                if (segments)
                    segments_[i] = media_segment(view_, ray.origin, ray.dir, INFINITY, b->weight[i],
                                                 b->pixel[i]);
            }
            const size_t base = next.size();
            if (b == &diffuse) { // as many as the rays gathered: refused before they are taken
                memory_.add(int64_t(count * sizeof(SurfaceHit)));
                gathered_bytes += int64_t(count * sizeof(SurfaceHit));
            }
            next.resize(base + count);
            fog_.assign(count, Vec3(0.0f));
            parallel_for(
                "shade.next", b->size(),
                [&](size_t i) {
                    if (r.closest[i] == kNoHit) return;
                    SurfaceHit& h = next[base + slot[i]];
                    h = bounce_hit(view_, b->rays[i], r.closest[i], b->pixel[i], b->weight[i],
                                   fog_[slot[i]], segments ? &segments_[i] : nullptr);
                    if (b->type == RayType::Diffuse) h.gather = b->light[i];
                },
                1024);
            if (scene_.lights_the_way()) // in ray order: the same sums on every accel
                for (size_t k = 0; k < count; ++k) radiance_[next[base + k].pixel] += fog_[k];
            if (segments) {
                t.stop(); // scatter_light times its own phases
                scatter_light(segments_);
                release_segments();
            }
        }
        memory_.sub(hit_bytes_); // the wave shaded here goes when its successor comes back
        hit_bytes_ = gathered_bytes;
        return next;
    }

    // Box filter of the aa x aa samples of each pixel; passes from the centre sample.
    void resolve() {
        PhaseTimer t(st_, "time_ms.shading");
        const int aa = s_.aa_samples, w = s_.width, h = s_.height;
        f_.width = w, f_.height = h;
        const size_t pixels = size_t(w) * h;
        // Only the passes the frame keeps (output.passes); the others stay empty.
        auto keep = [&](auto& pass, PassBit bit, size_t per_pixel) {
            if (!s_.keeps(bit)) return decltype(pass.data())(nullptr);
            pass.resize(pixels * per_pixel);
            return pass.data();
        };
        const SampleBuffers in{radiance_.data(), tests_.data(), depth_.data(),
                               normal_.data(),   albedo_.data(), object_.data()};
        const float gamma = scene_.working_gamma;
        const PixelBuffers out{
            keep(f_.rgba, kPassCombined, 4),      keep(f_.depth, kPassDepth, 1),
            keep(f_.normal, kPassNormal, 1),      keep(f_.albedo, kPassAlbedo, 1),
            keep(f_.object_id, kPassObjectId, 1), keep(f_.tests, kPassTests, 1)};
        parallel_for(
            "resolve", pixels, [&](size_t p) { resolve_pixel(p, w, aa, W_, gamma, in, out); },
            1024);
    }

    const PreparedScene& scene_;
    SceneView view_{scene_}; // and the frame's photon map
    PhotonMap photons_;
    const RenderSettings& s_;
    const ProgressFn& progress_;
    Frame& f_;
    Stats& st_;
    MemoryTracker memory_;
    RayGenParams params_;
    std::shared_ptr<const CullUnits> units_;
    int W_ = 0, H_ = 0;
    std::vector<Vec3> radiance_;
    std::vector<float> depth_;
    std::vector<Vec3> normal_, albedo_;
    std::vector<Vec3> fog_; // fog colour brought by each hit of the wave being built
    std::vector<uint32_t> object_;
    std::vector<uint32_t> tests_;
    bool scatter_ = false;               // media scatter the lights that cast shadows
    std::vector<MediaSegment> segments_; // the ways of the rays being shaded, for scatter_light
    int64_t hit_bytes_ = 0; // the current wave's gathered points, counted by memory_
};

} // namespace

Frame render_frame_cpu(const PreparedScene& scene, const RenderSettings& s,
                       const ProgressFn& progress) {
    Frame f;
    tbb::task_arena arena(s.threads > 0 ? s.threads : tbb::task_arena::automatic);
    arena.execute([&] { FramePipeline(scene, s, progress, f).run(); });
    return f;
}

} // namespace sheaf
