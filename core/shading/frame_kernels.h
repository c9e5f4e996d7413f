// The per-pixel and per-hit steps of the frame pipeline, host-and-device: analytic primary
// rays, the visibility-buffer resolve, what a ray leaving the scene brings, fog, the terms
// that need no ray, a bounce ray's hit, and the box filter, which the frame pipeline
// (core/frame/frame_pipeline.h) launches on every exec.
#pragma once

#include "core/math/hd_math.h"
#include "core/raster/camera.h"
#include "core/raster/rasterizer.h"
#include "core/rays/ray_gen.h"
#include "core/rsh/trace.h"
#include "core/scene/analytic.h"
#include "core/scene/scene_view.h"
#include "core/shading/media.h"
#include "core/shading/media_light.h"
#include "core/shading/mesh_camera.h"
#include "core/shading/rainbow.h"
#include "core/shading/shade.h"
#include "core/shading/surface_hit.h"
#include "core/shading/surface_texture.h"

#include <cstdint>
#include <cstring>

namespace sheaf {

/// Analytic objects ray-cast at the centre of pixel (x, y), merged into the pixel's
/// visibility key `vis` by the same depth key as the rasterised triangles.
SHEAF_HD_INLINE uint64_t cast_analytic_pixel(const SceneView& scene, const CameraFrame& cam, int x,
                                             int y, uint64_t vis) {
    const uint32_t first = scene.tri_count;
    const Ray ray = cam.pixel_ray(x, y);
    const float depth_per_t = cam.ortho ? 1.0f : dot(ray.dir, cam.forward);
    for (uint32_t a = 0; a < scene.analytic_count; ++a) {
        if (scene.prim_flag(first + a, kNoImage)) continue;
        const Sphere& s = scene.prim_sphere[first + a];
        if (!ray_meets_sphere(s, ray.origin, ray.dir)) continue;
        // Its box missed, or wholly behind the nearest surface so far (none of its hits
        // would be in front).
        float enter;
        if (!ray_enters_box(scene.analytic_box[a], ray.origin, ray.dir, enter)) continue;
        if (vis != kEmptyPixel) {
            const uint32_t near_bits = uint32_t(vis >> 32);
            float nearest;
            memcpy(&nearest, &near_bits, 4);
            if (enter * depth_per_t > nearest) continue;
        }
        AnalyticHit h;
        if (!analytic_first_hit(scene, a, ray, h)) continue;
        const float depth = h.t * depth_per_t;
        uint32_t bits;
        memcpy(&bits, &depth, 4);
        const uint64_t key = (uint64_t(bits) << 32) | (first + a);
        if (key < vis) vis = key;
    }
    return vis;
}

/// What a ray of sample `pixel` from `origin` leaving the scene along `dir` brings with weight
/// w: the sky, through the fog, and the light of the media it crosses.
SHEAF_HD_INLINE Vec3 leave_scene(const SceneView& scene, Vec3 origin, Vec3 dir, Vec3 w,
                                 uint32_t pixel) {
    Vec3 keep, add;
    fog_over(scene.fog, origin, dir, INFINITY, keep, add);
    Vec3 media_keep(1.0f), media_add(0.0f);
    if (scene.has_media())
        media_along(scene, origin, dir, INFINITY, media_keep, media_add, media_jitter(pixel));
    Vec3 sky = sky_color(scene, dir);
    if (scene.rainbow_count > 0) { // on the sky, before the fog
        Vec3 mul, rb;
        rainbow_over(scene, dir, kAtmosphereFar, pixel, mul, rb);
        sky = sky * mul + rb;
    }
    return w * ((sky * keep + add) * media_keep + media_add * keep);
}

/// Whether the way to hit h lies inside a solid object: the ray leaves, through its far
/// side, a closed object that is not `hollow` (kSolid, not kPrimOpen). No surface lies
/// between the way's ends, so the whole way is inside it. (A ray that meets the far side
/// of a clipped object may have come in through the opening.)
SHEAF_HD_INLINE bool way_in_solid(const SceneView& scene, const SurfaceHit& h) {
    return !h.front && scene.prim_flag(h.prim, kSolid) && !scene.prim_flag(h.prim, kPrimOpen);
}

/// The fog between the ray's origin and the hit: scales the hit's throughput, and returns
/// the fog's own colour the ray brings. The media of the containers on the way come first:
/// they fade the hit and add their own light. `seg`, when given, receives the way's media
/// segment (core/shading/media_light.h). As in POV-Ray, fog fills only the space outside
/// objects and inside hollow ones: a way inside a solid object takes none (way_in_solid).
SHEAF_HD_INLINE Vec3 through_fog(const SceneView& scene, SurfaceHit& h,
                                 MediaSegment* seg = nullptr) {
    const Vec3 origin = h.position - h.incoming * h.t;
    const bool no_fog = way_in_solid(scene, h);
    if (seg) *seg = media_segment(scene, origin, h.incoming, h.t, h.throughput, h.pixel, no_fog);
    Vec3 media(0.0f);
    if (scene.has_media()) {
        Vec3 keep, add;
        media_along(scene, origin, h.incoming, h.t, keep, add, media_jitter(h.pixel));
        media = h.throughput * add;
        h.throughput = h.throughput * keep;
    }
    if (scene.rainbow_count > 0) { // after the media, before the fog
        Vec3 mul, rb;
        rainbow_over(scene, h.incoming, h.t, h.pixel, mul, rb);
        media += h.throughput * rb;
        h.throughput = h.throughput * mul;
    }
    Vec3 keep(1.0f), add(0.0f);
    if (!no_fog) fog_over(scene.fog, origin, h.incoming, h.t, keep, add);
    const Vec3 fog = h.throughput * add + media * keep;
    h.throughput = h.throughput * keep;
    return fog;
}

/// The camera's ray for sample (x, y): the projection's, or a mesh camera's from the scene's
/// camera faces; false where there is none (the sample stays black).
SHEAF_HD_INLINE bool camera_ray(const SceneView& scene, const CameraFrame& cam, int x, int y,
                                Ray& r) {
    if (cam.projection == Projection::Mesh) return mesh_camera_ray(scene, cam, x, y, r);
    return cam.camera_ray(x, y, r);
}

/// The primary ray through the centre of pixel (x, y), tilted by the camera normal when there
/// is one (Camera::normal); false where the projection has none (the pixel stays black).
SHEAF_HD_INLINE bool primary_ray(const SceneView& scene, const CameraFrame& cam, int x, int y,
                                 Ray& r) {
    if (!camera_ray(scene, cam, x, y, r)) return false;
    if (cam.normal >= 0) {
        const float u = (float(x) + 0.5f) / float(cam.width) - 0.5f;
        const float v = 0.5f - (float(y) + 0.5f) / float(cam.height);
        r.dir = perturb_normal(scene, uint32_t(cam.normal), Vec3(u, v, 0.0f), r.dir);
    }
    return true;
}

/// One sample of the visibility buffer resolved: its surface (when something was hit), the
/// radiance it starts with (background or fog) and the primary passes.
struct PrimarySample {
    bool hit = false;
    SurfaceHit h;
    Vec3 radiance;
    float depth = INFINITY;
    Vec3 normal, albedo;
    uint32_t object = 0xFFFFFFFFu;
    MediaSegment segment; // the camera ray's way, for the light its media scatter
};

/// Sample i (x = i % W, y = i / W) with visibility key `vis`: the pixel's camera ray meets the
/// visible triangle's plane (or the analytic primitive) at the exact position. A sample the
/// projection has no ray for is black.
SHEAF_HD_INLINE PrimarySample primary_sample(const SceneView& scene, const CameraFrame& cam, int W,
                                             size_t i, uint64_t vis) {
    PrimarySample out;
    Ray ray;
    if (!primary_ray(scene, cam, int(i % size_t(W)), int(i / size_t(W)), ray)) return out;
    if (vis == kEmptyPixel) {
        out.radiance = leave_scene(scene, ray.origin, ray.dir, Vec3(1.0f), uint32_t(i));
        out.segment = media_segment(scene, ray.origin, ray.dir, INFINITY, Vec3(1.0f), uint32_t(i));
        return out;
    }
    const uint32_t prim = vis_prim(vis);
    float t = 0;
    if (scene.is_triangle(prim)) {
        // The exact hit of the pixel's ray with the visible triangle's plane.
        const TriangleVerts& tv = scene.tris[prim];
        const Vec3 n = cross(tv.b - tv.a, tv.c - tv.a);
        const float dn = dot(ray.dir, n);
        t = dn != 0 ? dot(tv.a - ray.origin, n) / dn : 0.0f;
    } else {
        AnalyticHit a;
        if (analytic_first_hit(scene, prim - scene.tri_count, ray, a)) t = a.t;
    }
    if (!(t > 0) || !(t <= FLT_MAX)) t = 0; // not positive, NaN or infinite
    SurfaceHit h = make_surface_hit(scene, ray, prim, t);
    h.pixel = uint32_t(i);
    h.throughput = Vec3(1.0f);
    out.radiance = through_fog(scene, h, &out.segment);
    out.hit = true;
    out.h = h;
    out.depth = t;
    out.normal = h.normal;
    out.albedo = h.albedo;
    out.object = scene.prim_object[prim];
    return out;
}

/// The light the frame's photon map brings to h (POV-Ray's caustics): every photon the
/// search finds lights h as a light from where it came, its power over the cosine between
/// that way and the geometric normal (at least 0.1), all over the searched disc's area.
/// Objects that collect no photons gather none; photons from behind the surface bring
/// nothing. Not inlined: the search's stack (512 bytes) stays out of the shading kernels'
/// frames.
SHEAF_HD_NOINLINE Vec3 photon_light(const SceneView& scene, const Material& m,
                                    const SurfaceHit& h) {
    const PhotonMapView& pm = scene.photon_map;
    if (pm.count == 0 || (m.diffuse == 0 && m.specular == 0 && m.blinn == 0)) return Vec3(0.0f);
    if (scene.prim_flag(h.prim, kNoPhotonCollect)) return Vec3(0.0f);
    float r2 = 0;
    if (photon_gather(pm, h.position, h.geo_normal, r2) == 0 || !(r2 > 0)) return Vec3(0.0f);
    Vec3 sum(0.0f);
    for_photons_near(pm, h.position, h.geo_normal, r2, [&](const Photon& ph) {
        if (dot(h.normal, ph.from) < 1e-5f) return;
        const float cos_raw = hdm::fmaxf(0.1f, hdm::fminf(1.0f, dot(h.geo_normal, ph.from)));
        sum += direct_light(m, h, ph.from, ph.power / cos_raw);
    });
    return sum / (kPi * r2);
}

/// The terms of hit h that need no ray: emission, ambient (unless AO traces it), the photon
/// map's light, shadowless lights; weighted by the hit's throughput.
SHEAF_HD_INLINE Vec3 unshadowed_terms(const SceneView& scene, const SurfaceHit& h, bool trace_ao,
                                      const RayGenParams& p) {
    const Material& m = scene.materials[h.material];
    Vec3 c = m.emission;
    if (!trace_ao) c += ambient_light(m, h);
    // photon_light is called, not inlined: only when the frame has photons.
    if (scene.photon_map.count > 0) c += photon_light(scene, m, h);
    for (uint32_t li = 0; li < scene.light_count; ++li) {
        const Light& l = scene.lights[li];
        if (!l.shadowless || !lights_point(l, h, p)) continue;
        const LightSample ls = sample_light(l, h.position, p.far);
        c += direct_light(m, h, ls.to_light, ls.radiance, l.highlights);
    }
    return h.throughput * c;
}

/// The surface a reflection or refraction ray found (closest != kNoHit), carrying the ray's
/// weight; light leaving an object through its far side fades by its interior, then the fog
/// on the way scales it. `fog` receives the fog's colour the ray brings.
SHEAF_HD_INLINE SurfaceHit bounce_hit(const SceneView& scene, const Ray& ray, uint64_t closest,
                                      uint32_t pixel, Vec3 weight, Vec3& fog,
                                      MediaSegment* seg = nullptr) {
    SurfaceHit h = make_surface_hit(scene, ray, hit_prim(closest), hit_t(closest));
    h.pixel = pixel;
    h.throughput = weight;
    // Leaving an object through its far side: what its interior faded.
    if (!h.front) h.throughput = h.throughput * interior_fade(scene.materials[h.material], h.t);
    fog = through_fog(scene, h, seg);
    return h;
}

/// The per-sample buffers a frame resolves from (W x H samples, aa x aa per pixel).
struct SampleBuffers {
    const Vec3* radiance;
    const uint32_t* tests;
    const float* depth;
    const Vec3* normal;
    const Vec3* albedo;
    const uint32_t* object;
};

/// The frame's per-pixel outputs (w x h); a pass the frame does not keep (output.passes) is
/// null.
struct PixelBuffers {
    float* rgba;
    float* depth;
    Vec3* normal;
    Vec3* albedo;
    uint32_t* object;
    uint32_t* tests;
};

/// Box filter of the aa x aa samples of pixel p, taken from the scene's working space to light
/// (v^gamma; POV-Ray averages in its working space too); passes from the centre sample.
SHEAF_HD_INLINE void resolve_pixel(size_t p, int w, int aa, int W, float gamma,
                                   const SampleBuffers& in, const PixelBuffers& out) {
    const int x = int(p % size_t(w)), y = int(p / size_t(w));
    if (out.tests) {
        uint64_t tests = 0;
        for (int sy = 0; sy < aa; ++sy)
            for (int sx = 0; sx < aa; ++sx)
                tests += in.tests[size_t(y * aa + sy) * W + (x * aa + sx)];
        out.tests[p] = uint32_t(tests < 0xFFFFFFFFu ? tests : 0xFFFFFFFFu);
    }
    if (out.rgba) {
        const float inv = 1.0f / float(aa * aa);
        Vec3 sum(0.0f);
        for (int sy = 0; sy < aa; ++sy)
            for (int sx = 0; sx < aa; ++sx)
                sum += in.radiance[size_t(y * aa + sy) * W + (x * aa + sx)];
        sum = sum * inv;
        if (gamma != 1)
            for (int c = 0; c < 3; ++c) sum[c] = sum[c] > 0 ? hdm::powf(sum[c], gamma) : sum[c];
        out.rgba[4 * p + 0] = sum.x, out.rgba[4 * p + 1] = sum.y, out.rgba[4 * p + 2] = sum.z,
                         out.rgba[4 * p + 3] = 1;
    }
    const size_t c = size_t(y * aa + aa / 2) * W + (x * aa + aa / 2);
    if (out.depth) out.depth[p] = in.depth[c];
    if (out.normal) out.normal[p] = in.normal[c];
    if (out.albedo) out.albedo[p] = in.albedo[c];
    if (out.object) out.object[p] = in.object[c];
}

} // namespace sheaf
