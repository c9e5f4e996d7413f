#include "core/frame/frame_stats.h"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace sheaf {

void declare_frame_keys(Stats& st) {
    for (const char* k : {"rays.primary", "rays.shadow", "rays.reflection", "rays.refraction",
                          "rays.ao", "rays.diffuse", "rays.camera"})
        st.set(k, 0);
    for (const char* k :
         {"time_ms.raster", "time_ms.gbuffer", "time_ms.ray_creation", "time_ms.hashing",
          "time_ms.compression", "time_ms.sorting", "time_ms.decompression", "time_ms.hierarchy",
          "time_ms.traversal", "time_ms.final_tests", "time_ms.shading", "time_ms.frame"})
        st.set(k, 0);
}

float scene_extent(const PreparedScene& scene) {
    float e = geometry_extent(scene);
    for (const Light& l : scene.lights) e = std::max(e, length(l.position));
    return e;
}

float geometry_extent(const PreparedScene& scene) {
    float e = 1e-3f;
    for (const Sphere& s : scene.object_sphere) // unbounded objects (planes) do not count
        if (std::isfinite(s.radius)) e = std::max(e, length(s.center) + s.radius);
    return std::max(e, length(scene.camera.position));
}

RayGenParams frame_ray_params(const PreparedScene& scene, const RenderSettings& s) {
    RayGenParams p;
    // Rays that leave surfaces start off them by the rounding of the hit point, which grows
    // with the point's coordinates (surface_offset) and the camera's distance: neither a light
    // far away nor a sky sphere of radius 1e5 pushes them past surfaces 0.001 apart. Shadow
    // rays start at the lights, so their end keeps the lights' offset too.
    p.epsilon = kRelativeOffset * std::max(length(scene.camera.position), 1e-3f);
    float lights = 1e-3f;
    for (const Light& l : scene.lights) lights = std::max(lights, length(l.position));
    p.shadow_epsilon = kRelativeOffset * lights;
    p.far = 4.0f * scene_extent(scene);
    p.min_weight = s.trace_bailout;
    p.ao_samples = s.ao_samples;
    p.ao_distance = s.ao_distance;
    p.radiosity_samples = s.radiosity_samples;
    p.radiosity_depth = s.radiosity_depth;
    p.radiosity_brightness = s.radiosity_brightness;
    return p;
}

void frame_totals(Stats& st, const PreparedScene& scene, const RenderSettings& s, int64_t peak) {
    double total = 0, brute = 0, objects = 0;
    for (int t = 0; t < kRayTypeCount; ++t) {
        const std::string p = std::string("tests.") + ray_type_name(RayType(t)) + ".";
        total += st.get(p + "total");
        brute += st.get(p + "brute_force");
        objects += st.get(p + "objects.tests");
    }
    st.set("rays.secondary", st.get("rays.shadow") + st.get("rays.reflection") +
                                 st.get("rays.refraction") + st.get("rays.ao") +
                                 st.get("rays.diffuse"));
    st.set("tests.total", total);
    st.set("tests.objects", objects);
    st.set("tests.brute_force", brute);
    st.set("tests.share_of_brute_force", brute > 0 ? total / brute : 0.0);
    st.set("frame.width", s.width);
    st.set("frame.height", s.height);
    st.set("frame.samples_per_pixel", s.aa_samples * s.aa_samples);
    st.set("scene.primitives", double(scene.prim_count()));
    st.set("scene.objects", double(scene.object_count()));
    st.set("scene.lights", double(scene.lights.size()));
    st.set("memory.peak_bytes", double(peak));
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    st.set("memory.process_peak_rss_bytes", double(ru.ru_maxrss) * 1024.0);
}

} // namespace sheaf
