#include "core/rays/ray_gen.h"

#include "core/base/parallel.h"
#include "core/render/shade.h"
#include "core/sort/radix_sort.h"

#include <cfloat>

namespace sheaf {

float radical_inverse(uint32_t i, uint32_t base) {
    const float inv = 1.0f / float(base);
    float f = inv, r = 0;
    while (i > 0) {
        r += f * float(i % base);
        i /= base;
        f *= inv;
    }
    return r;
}

namespace {

// Calls count(i) for every hit, scans the counts, then fill(i, first_slot): the output order
// is hit order, then the order each hit emits in, whatever the thread schedule.
template <class Count, class Fill>
void emit(size_t hits, RayBatch& out, const Count& count, const Fill& fill) {
    std::vector<uint32_t> offset(hits);
    parallel_for(
        "raygen.count", hits, [&](size_t i) { offset[i] = count(i); }, 1024);
    const uint32_t total = exclusive_scan_inplace(offset);
    out.resize(total);
    parallel_for(
        "raygen.fill", hits, [&](size_t i) { fill(i, offset[i]); }, 1024);
}

// A frame around unit n.
void basis(Vec3 n, Vec3& t, Vec3& b) {
    const float s = n.z >= 0 ? 1.0f : -1.0f;
    const float a = -1.0f / (s + n.z);
    const float c = n.x * n.y * a;
    t = Vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
    b = Vec3(c, s + n.y * n.y * a, -n.y);
}

} // namespace

bool lights_point(const Light& l, const SurfaceHit& h, const RayGenParams& p) {
    const LightSample s = sample_light(l, h.position, p.far);
    return dot(h.geo_normal, s.to_light) > 0 && dot(h.normal, s.to_light) > 0 &&
           max_component(s.radiance) > 0;
}

void generate_shadow_rays(const PreparedScene& scene, const std::vector<SurfaceHit>& hits,
                          const RayGenParams& p, RayBatch& out) {
    // Light-major order: all rays of light 0 in hit order, then light 1, ... Rays that leave
    // the same light towards neighbouring pixels sit side by side even unsorted (rah).
    const size_t n = hits.size();
    const auto& lights = scene.lights;
    emit(
        n * lights.size(), out,
        [&](size_t k) {
            const Light& l = lights[k / n];
            return !l.shadowless && lights_point(l, hits[k % n], p) ? 1u : 0u;
        },
        [&](size_t k, uint32_t slot) {
            const SurfaceHit& h = hits[k % n];
            const uint32_t li = uint32_t(k / n);
            const Light& l = lights[li];
            if (l.shadowless || !lights_point(l, h, p)) return;
            // The ray starts at the light and ends just above the surface.
            const Vec3 target = h.position + h.geo_normal * p.epsilon;
            const LightSample ls = sample_light(l, target, p.far);
            Ray r;
            r.origin = ls.origin;
            r.dir = -ls.to_light;
            r.tmin = 0.0f;
            r.tmax = ls.distance;
            out.rays[slot] = r;
            out.pixel[slot] = h.pixel;
            out.weight[slot] =
                h.throughput * direct_light(scene.materials[h.material], h, ls.to_light, ls.radiance);
            out.light[slot] = li;
        });
}

void generate_ao_rays(const PreparedScene& scene, const std::vector<SurfaceHit>& hits,
                      const RayGenParams& p, RayBatch& out) {
    const uint32_t n = uint32_t(p.ao_samples);
    if (n == 0) {
        out.resize(0);
        return;
    }
    emit(
        hits.size(), out, [&](size_t) { return n; },
        [&](size_t i, uint32_t slot) {
            const SurfaceHit& h = hits[i];
            const Material& m = scene.materials[h.material];
            const Vec3 w = h.throughput * ambient_light(m, h) * (1.0f / float(n));
            Vec3 t, b;
            basis(h.geo_normal, t, b);
            for (uint32_t s = 0; s < n; ++s) {
                // Cosine-weighted hemisphere from the Halton points (bases 2 and 3).
                const uint32_t index = h.pixel * n + s + 1;
                const float u1 = radical_inverse(index, 2), u2 = radical_inverse(index, 3);
                const float r = sqrtf(u1), phi = 2.0f * kPi * u2;
                const Vec3 d = t * (r * cosf(phi)) + b * (r * sinf(phi)) +
                               h.geo_normal * sqrtf(fmaxf(0.0f, 1.0f - u1));
                Ray ray;
                ray.origin = h.position + h.geo_normal * p.epsilon;
                ray.dir = normalize(d);
                ray.tmin = 0.0f;
                ray.tmax = p.ao_distance;
                out.rays[slot + s] = ray;
                out.pixel[slot + s] = h.pixel;
                out.weight[slot + s] = w;
            }
        });
}

namespace {

struct BounceSplit {
    Vec3 reflect_weight, refract_weight;
    Vec3 reflect_dir, refract_dir;
};

BounceSplit split(const PreparedScene& scene, const SurfaceHit& h) {
    const Material& m = scene.materials[h.material];
    BounceSplit s{};
    // Light passing through: tinted by the colour (filter) or not (transmit).
    const Vec3 pass = h.albedo * h.filter + Vec3(h.transmit);
    const Vec3 mirror = mirror_weight(m, h);
    Vec3 reflect_w = mirror;
    if (max_component(pass) > 0) {
        // Entering from outside the object: n_outside / n_inside; leaving: the inverse.
        const float eta = h.front ? 1.0f / m.ior : m.ior;
        float kr = 0.0f;
        if (m.fresnel_split) {
            const float cos_i = fminf(1.0f, fmaxf(0.0f, -dot(h.normal, h.incoming)));
            kr = fresnel_dielectric(cos_i, eta);
        }
        if (kr < 1.0f && refract(h.incoming, h.normal, eta, s.refract_dir)) {
            float keep = 1.0f - kr;
            if (m.conserve_energy) keep *= fmaxf(0.0f, 1.0f - max_component(mirror));
            s.refract_weight = h.throughput * pass * keep;
        } else {
            kr = 1.0f; // total internal reflection: what would pass is reflected
        }
        reflect_w += pass * kr;
    }
    s.reflect_weight = h.throughput * reflect_w;
    s.reflect_dir = reflect(h.incoming, h.normal);
    // A shading normal can send a reflection below the surface; the geometric one cannot.
    if (dot(s.reflect_dir, h.geo_normal) <= 0) s.reflect_dir = reflect(h.incoming, h.geo_normal);
    return s;
}

} // namespace

void generate_bounce_rays(const PreparedScene& scene, const std::vector<SurfaceHit>& hits,
                          const RayGenParams& p, RayBatch& refl, RayBatch& refr) {
    std::vector<BounceSplit> splits(hits.size());
    parallel_for(
        "raygen.split", hits.size(), [&](size_t i) { splits[i] = split(scene, hits[i]); }, 1024);
    emit(
        hits.size(), refl,
        [&](size_t i) { return max_component(splits[i].reflect_weight) > p.min_weight ? 1u : 0u; },
        [&](size_t i, uint32_t slot) {
            if (max_component(splits[i].reflect_weight) <= p.min_weight) return;
            const SurfaceHit& h = hits[i];
            Ray r;
            r.origin = h.position + h.geo_normal * p.epsilon;
            r.dir = splits[i].reflect_dir;
            r.tmin = 0.0f;
            r.tmax = FLT_MAX;
            refl.rays[slot] = r;
            refl.pixel[slot] = h.pixel;
            refl.weight[slot] = splits[i].reflect_weight;
        });
    emit(
        hits.size(), refr,
        [&](size_t i) { return max_component(splits[i].refract_weight) > p.min_weight ? 1u : 0u; },
        [&](size_t i, uint32_t slot) {
            if (max_component(splits[i].refract_weight) <= p.min_weight) return;
            const SurfaceHit& h = hits[i];
            Ray r;
            r.origin = h.position - h.geo_normal * p.epsilon; // below the surface
            r.dir = splits[i].refract_dir;
            r.tmin = 0.0f;
            r.tmax = FLT_MAX;
            refr.rays[slot] = r;
            refr.pixel[slot] = h.pixel;
            refr.weight[slot] = splits[i].refract_weight;
        });
}

} // namespace sheaf
