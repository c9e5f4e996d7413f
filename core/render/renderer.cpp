#include "core/render/renderer.h"

#include "core/base/error.h"
#include "core/base/parallel.h"
#include "core/base/timer.h"
#include "core/raster/rasterizer.h"
#include "core/rays/ray_gen.h"
#include "core/render/shade.h"
#include "core/render/surface_texture.h"
#include "core/rsh/trace.h"
#include "core/scene/analytic.h"

#include <tbb/task_arena.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

namespace sheaf {
namespace {

// Every frame lists the same keys in the same order, whatever the scene exercises.
void declare_keys(Stats& st) {
    for (const char* k :
         {"rays.primary", "rays.shadow", "rays.reflection", "rays.refraction", "rays.ao"})
        st.set(k, 0);
    for (const char* k :
         {"time_ms.raster", "time_ms.gbuffer", "time_ms.ray_creation", "time_ms.hashing",
          "time_ms.compression", "time_ms.sorting", "time_ms.decompression", "time_ms.hierarchy",
          "time_ms.traversal", "time_ms.final_tests", "time_ms.shading", "time_ms.frame"})
        st.set(k, 0);
}

float scene_extent(const PreparedScene& scene) {
    float e = 1e-3f;
    for (const Sphere& s : scene.object_sphere) // unbounded objects (planes) do not count
        if (std::isfinite(s.radius)) e = std::max(e, length(s.center) + s.radius);
    for (const Light& l : scene.lights) e = std::max(e, length(l.position));
    return std::max(e, length(scene.camera.position));
}

class FramePipeline {
  public:
    FramePipeline(const PreparedScene& scene, const RenderSettings& s, const ProgressFn& progress,
                  Frame& f)
        : scene_(scene), s_(s), progress_(progress), f_(f), st_(f.stats) {}

    void run() {
        declare_keys(st_);
        PhaseTimer frame_timer(st_, "time_ms.frame");
        const int aa = s_.aa_samples;
        W_ = s_.width * aa, H_ = s_.height * aa;
        radiance_.assign(size_t(W_) * H_, Vec3(0.0f));
        tests_.assign(size_t(W_) * H_, 0);
        memory_.add(int64_t(radiance_.size() * sizeof(Vec3)));
        params_.epsilon = 1e-5f * scene_extent(scene_);
        params_.far = 4.0f * scene_extent(scene_);
        params_.ao_samples = s_.ao_samples;
        params_.ao_distance = s_.ao_distance;

        std::vector<SurfaceHit> hits = primary();
        report(0.1f);
        for (int bounce = 0; bounce <= s_.trace_depth && !hits.empty(); ++bounce) {
            hits = shade_wave(hits, bounce);
            report(0.1f + 0.9f * float(bounce + 1) / float(s_.trace_depth + 1));
        }
        resolve();
        frame_timer.stop();
        totals();
    }

  private:
    void report(float done) {
        if (progress_ && !progress_(done)) throw RenderError("cancelled");
    }

    // Analytic objects are ray-cast at the pixel centres and merged into the visibility buffer
    // by the same depth key as the rasterised triangles.
    void cast_analytic(const CameraFrame& cam, std::vector<uint64_t>& vis) {
        const uint32_t first = uint32_t(scene_.tris.size());
        const uint32_t count = uint32_t(scene_.analytic_root.size());
        if (count == 0) return;
        parallel_for(
            "raster.analytic", vis.size(),
            [&](size_t i) {
                const Ray ray = cam.pixel_ray(int(i % W_), int(i / W_));
                const float depth_per_t = cam.ortho ? 1.0f : dot(ray.dir, cam.forward);
                for (uint32_t a = 0; a < count; ++a) {
                    if (scene_.prim_flag(first + a, kNoImage)) continue;
                    const Sphere& s = scene_.prim_sphere[first + a];
                    if (std::isfinite(s.radius)) { // the bounding sphere first
                        const Vec3 oc = s.center - ray.origin;
                        const float along = dot(oc, ray.dir);
                        if (length_squared(oc) - along * along > s.radius * s.radius ||
                            (along < -s.radius && length(oc) > s.radius))
                            continue;
                    }
                    AnalyticHit h;
                    if (!analytic_first_hit(scene_, a, ray, h)) continue;
                    const float depth = h.t * depth_per_t;
                    uint32_t bits;
                    std::memcpy(&bits, &depth, 4);
                    const uint64_t key = (uint64_t(bits) << 32) | (first + a);
                    if (key < vis[i]) vis[i] = key;
                }
            },
            256);
    }

    // Rasterised primary visibility, resolved to surface hits and the primary passes.
    std::vector<SurfaceHit> primary() {
        const CameraFrame cam = make_camera_frame(scene_.camera, W_, H_);
        std::vector<uint64_t> vis;
        {
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
        parallel_for(
            "gbuffer.resolve", vis.size(),
            [&](size_t i) {
                const Ray ray = cam.pixel_ray(int(i % W_), int(i / W_));
                if (vis[i] == kEmptyPixel) {
                    radiance_[i] = leave_scene(ray.dir, Vec3(1.0f));
                    return;
                }
                const uint32_t prim = vis_prim(vis[i]);
                float t = 0;
                if (scene_.is_triangle(prim)) {
                    // The exact hit of the pixel's ray with the visible triangle's plane.
                    const TriangleVerts& tv = scene_.tris[prim];
                    const Vec3 n = cross(tv.b - tv.a, tv.c - tv.a);
                    const float dn = dot(ray.dir, n);
                    t = dn != 0 ? dot(tv.a - ray.origin, n) / dn : 0.0f;
                } else {
                    AnalyticHit a;
                    if (analytic_first_hit(scene_, prim - uint32_t(scene_.tris.size()), ray, a))
                        t = a.t;
                }
                if (!(t > 0) || !std::isfinite(t)) t = 0;
                SurfaceHit h = make_surface_hit(scene_, ray, prim, t);
                h.pixel = uint32_t(i);
                h.throughput = Vec3(1.0f);
                radiance_[i] = through_fog(h);
                hits[slot[i]] = h;
                depth_[i] = t;
                normal_[i] = h.normal;
                albedo_[i] = h.albedo;
                object_[i] = scene_.prim_object[prim];
            },
            1024);
        memory_.sub(int64_t(vis.size() * sizeof(uint64_t)));
        return hits;
    }

    // What a ray leaving the scene along `dir` brings with weight w: the sky, through the fog.
    Vec3 leave_scene(Vec3 dir, Vec3 w) const {
        float keep;
        Vec3 add;
        fog_over(scene_.fog, INFINITY, keep, add);
        return w * (sky_color(scene_, dir) * keep + add);
    }

    // The fog between the ray's origin and the hit: scales the hit's throughput, and returns
    // the fog's own colour the ray brings.
    Vec3 through_fog(SurfaceHit& h) const {
        float keep;
        Vec3 add;
        fog_over(scene_.fog, h.t, keep, add);
        const Vec3 fog = h.throughput * add;
        h.throughput = h.throughput * keep;
        return fog;
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

    // Shades one wave of hits; returns the hits of its reflection and refraction rays.
    std::vector<SurfaceHit> shade_wave(const std::vector<SurfaceHit>& hits, int bounce) {
        RayBatch shadow(RayType::Shadow, memory_), ao(RayType::Ao, memory_);
        const bool trace_ao = bounce == 0 && s_.ao_samples > 0;
        {
            PhaseTimer t(st_, "time_ms.ray_creation");
            generate_shadow_rays(scene_, hits, params_, shadow);
            if (trace_ao) generate_ao_rays(scene_, hits, params_, ao);
        }
        {
            // Terms that need no ray: emission, ambient (unless AO traces it), shadowless lights.
            PhaseTimer t(st_, "time_ms.shading");
            for (const SurfaceHit& h : hits) {
                const Material& m = scene_.materials[h.material];
                Vec3 c = m.emission;
                if (!trace_ao) c += ambient_light(m, h);
                for (const Light& l : scene_.lights) {
                    if (!l.shadowless || !lights_point(l, h, params_)) continue;
                    const LightSample ls = sample_light(l, h.position, params_.far);
                    c += direct_light(m, h, ls.to_light, ls.radiance);
                }
                radiance_[h.pixel] += h.throughput * c;
            }
        }
        TraceResult r;
        trace_batch(scene_, shadow, s_, st_, memory_, r);
        {
            PhaseTimer t(st_, "time_ms.shading");
            accumulate(shadow, r);
            count_tests(shadow, r);
        }
        if (trace_ao) {
            trace_batch(scene_, ao, s_, st_, memory_, r);
            PhaseTimer t(st_, "time_ms.shading");
            accumulate(ao, r);
            count_tests(ao, r);
        }
        if (bounce >= s_.trace_depth) return {};

        RayBatch refl(RayType::Reflection, memory_), refr(RayType::Refraction, memory_);
        {
            PhaseTimer t(st_, "time_ms.ray_creation");
            generate_bounce_rays(scene_, hits, params_, refl, refr);
        }
        std::vector<SurfaceHit> next;
        for (RayBatch* b : {&refl, &refr}) {
            trace_batch(scene_, *b, s_, st_, memory_, r);
            PhaseTimer t(st_, "time_ms.shading");
            count_tests(*b, r);
            std::vector<uint32_t> slot(b->size());
            uint32_t count = 0;
            for (size_t i = 0; i < b->size(); ++i) {
                slot[i] = count;
                if (r.closest[i] != kNoHit)
                    ++count;
                else
                    radiance_[b->pixel[i]] += leave_scene(b->rays[i].dir, b->weight[i]);
            }
            const size_t base = next.size();
            next.resize(base + count);
            fog_.assign(count, Vec3(0.0f));
            parallel_for(
                "shade.next", b->size(),
                [&](size_t i) {
                    if (r.closest[i] == kNoHit) return;
                    SurfaceHit h = make_surface_hit(scene_, b->rays[i], hit_prim(r.closest[i]),
                                                    hit_t(r.closest[i]));
                    h.pixel = b->pixel[i];
                    h.throughput = b->weight[i];
                    // Leaving an object through its far side: what its interior faded.
                    if (!h.front)
                        h.throughput = h.throughput * interior_fade(scene_.materials[h.material], h.t);
                    fog_[slot[i]] = through_fog(h);
                    next[base + slot[i]] = h;
                },
                1024);
            if (scene_.fog.distance > 0) // in ray order: sums stay the same on every accel
                for (size_t k = 0; k < count; ++k) radiance_[next[base + k].pixel] += fog_[k];
        }
        return next;
    }

    // Box filter of the aa x aa samples of each pixel; passes from the centre sample.
    void resolve() {
        PhaseTimer t(st_, "time_ms.shading");
        const int aa = s_.aa_samples, w = s_.width, h = s_.height;
        f_.width = w, f_.height = h;
        f_.rgba.assign(size_t(w) * h * 4, 0.0f);
        f_.depth.resize(size_t(w) * h);
        f_.normal.resize(size_t(w) * h);
        f_.albedo.resize(size_t(w) * h);
        f_.object_id.resize(size_t(w) * h);
        f_.tests.resize(size_t(w) * h);
        const float inv = 1.0f / float(aa * aa);
        parallel_for(
            "resolve", size_t(w) * h,
            [&](size_t p) {
                const int x = int(p % w), y = int(p / w);
                Vec3 sum(0.0f);
                uint64_t tests = 0;
                for (int sy = 0; sy < aa; ++sy)
                    for (int sx = 0; sx < aa; ++sx) {
                        sum += radiance_[size_t(y * aa + sy) * W_ + (x * aa + sx)];
                        tests += tests_[size_t(y * aa + sy) * W_ + (x * aa + sx)];
                    }
                f_.tests[p] = uint32_t(std::min<uint64_t>(tests, 0xFFFFFFFFu));
                sum = sum * inv;
                f_.rgba[4 * p + 0] = sum.x, f_.rgba[4 * p + 1] = sum.y, f_.rgba[4 * p + 2] = sum.z,
                                f_.rgba[4 * p + 3] = 1;
                const size_t c = size_t(y * aa + aa / 2) * W_ + (x * aa + aa / 2);
                f_.depth[p] = depth_[c];
                f_.normal[p] = normal_[c];
                f_.albedo[p] = albedo_[c];
                f_.object_id[p] = object_[c];
            },
            1024);
    }

    void totals() {
        double total = 0, brute = 0, objects = 0;
        for (int t = 0; t < kRayTypeCount; ++t) {
            const std::string p = std::string("tests.") + ray_type_name(RayType(t)) + ".";
            total += st_.get(p + "total");
            brute += st_.get(p + "brute_force");
            objects += st_.get(p + "objects.tests");
        }
        st_.set("rays.secondary", st_.get("rays.shadow") + st_.get("rays.reflection") +
                                      st_.get("rays.refraction") + st_.get("rays.ao"));
        st_.set("tests.total", total);
        st_.set("tests.objects", objects);
        st_.set("tests.brute_force", brute);
        st_.set("tests.share_of_brute_force", brute > 0 ? total / brute : 0.0);
        st_.set("frame.width", s_.width);
        st_.set("frame.height", s_.height);
        st_.set("frame.samples_per_pixel", s_.aa_samples * s_.aa_samples);
        st_.set("scene.primitives", double(scene_.prim_count()));
        st_.set("scene.objects", double(scene_.object_count()));
        st_.set("scene.lights", double(scene_.lights.size()));
        st_.set("memory.peak_bytes", double(memory_.peak()));
        rusage ru{};
        getrusage(RUSAGE_SELF, &ru);
        st_.set("memory.process_peak_rss_bytes", double(ru.ru_maxrss) * 1024.0);
    }

    const PreparedScene& scene_;
    const RenderSettings& s_;
    const ProgressFn& progress_;
    Frame& f_;
    Stats& st_;
    MemoryTracker memory_;
    RayGenParams params_;
    int W_ = 0, H_ = 0;
    std::vector<Vec3> radiance_;
    std::vector<float> depth_;
    std::vector<Vec3> normal_, albedo_;
    std::vector<Vec3> fog_; // fog colour brought by each hit of the wave being built
    std::vector<uint32_t> object_;
    std::vector<uint32_t> tests_;
};

} // namespace

Frame render_frame(const PreparedScene& scene, const RenderSettings& s,
                   const ProgressFn& progress) {
    if (s.backend == Backend::Cuda)
        throw RenderError(
            "backend=cuda: this build has no CUDA backend yet; use backend=cpu or backend=auto");
    Frame f;
    tbb::task_arena arena(s.threads > 0 ? s.threads : tbb::task_arena::automatic);
    arena.execute([&] { FramePipeline(scene, s, progress, f).run(); });
    return f;
}

} // namespace sheaf
