// Object-space acceleration against Embree, side by side in one process: generated scenes of a
// terrain and 256 sphere meshes (real occlusion: the spheres shadow the terrain and each
// other), at several sizes. Embree casts the camera's primary rays (one per pixel) and its
// shadow rays to the light from every hit; Sheaf traces the very same shadow rays under each
// accel mode (trace_batch, the frame pipeline's tracer), then renders the whole frame under
// each mode. Build time, shadow trace time, Mrays/s, structure bytes per triangle.
//
// Usage: sheaf_accel_bench [--sizes 10000,100000,1000000] [--threads 2] [--width 512]
//                          [--modes crsh,bvh] [--rounds 3]
// Times are the median of the rounds. Embree 3 from Debian (libembree-dev) is a dependency of
// this benchmark only.
#include "bench_args.h"
#include "core/accel/bvh.h"
#include "core/frame/host_tracer.h"
#include "core/frame/render_frame.h"
#include "core/rsh/cull_units.h"

#include <embree3/rtcore.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace sheaf;

namespace {

using Clock = std::chrono::steady_clock;
double ms(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}
double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

const Vec3 kLight(30, 80, 20);

// A terrain of about `tris` triangles (a height field) and 256 icosahedron-based spheres
// (80 triangles each) standing on it.
Scene make_scene(size_t tris) {
    Scene s;
    s.add_material(Material{});
    const size_t sphere_tris = 256 * 80;
    const size_t terrain = tris > sphere_tris + 2 ? tris - sphere_tris : 2;
    const int g = std::max(1, int(std::sqrt(double(terrain) / 2.0)));
    const float size = 100.0f;
    const auto height = [](float x, float z) {
        return 3.0f * std::sin(x * 0.11f) * std::cos(z * 0.07f) + 1.2f * std::sin(x * 0.37f + z * 0.23f);
    };
    Mesh m;
    for (int j = 0; j <= g; ++j)
        for (int i = 0; i <= g; ++i) {
            const float x = -size / 2 + size * float(i) / float(g);
            const float z = -size / 2 + size * float(j) / float(g);
            m.positions.push_back({x, height(x, z), z});
        }
    for (int j = 0; j < g; ++j)
        for (int i = 0; i < g; ++i) {
            const uint32_t a = uint32_t(j * (g + 1) + i), b = a + 1, c = a + uint32_t(g + 1), d = c + 1;
            for (uint32_t v : {a, c, b, b, c, d}) m.indices.push_back(v);
        }
    s.add_mesh_object("terrain", std::move(m), 0);
    // An icosahedron subdivided once: 80 triangles on the unit sphere.
    std::vector<Vec3> ico = {{-1, 1.618f, 0}, {1, 1.618f, 0}, {-1, -1.618f, 0}, {1, -1.618f, 0},
                             {0, -1, 1.618f}, {0, 1, 1.618f}, {0, -1, -1.618f}, {0, 1, -1.618f},
                             {1.618f, 0, -1}, {1.618f, 0, 1}, {-1.618f, 0, -1}, {-1.618f, 0, 1}};
    const uint32_t faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    std::vector<Vec3> unit;
    for (const auto& f : faces) {
        const Vec3 a = normalize(ico[f[0]]), b = normalize(ico[f[1]]), c = normalize(ico[f[2]]);
        const Vec3 ab = normalize(a + b), bc = normalize(b + c), ca = normalize(c + a);
        for (const Vec3& v : {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca}) unit.push_back(v);
    }
    for (int k = 0; k < 256; ++k) {
        const float x = -40.0f + 80.0f * float(k % 16) / 15.0f + float((k * 7) % 5) * 0.6f;
        const float z = -40.0f + 80.0f * float(k / 16) / 15.0f + float((k * 3) % 7) * 0.5f;
        const float r = 1.0f + float((k * 13) % 9) * 0.25f;
        const Vec3 c(x, height(x, z) + r, z);
        Mesh sm;
        for (const Vec3& v : unit) {
            sm.positions.push_back(c + v * r);
            sm.indices.push_back(uint32_t(sm.positions.size() - 1));
        }
        s.add_mesh_object("ball" + std::to_string(k), std::move(sm), 0);
    }
    s.add_light(Light{kLight, Vec3(1.0f)});
    s.camera.position = Vec3(0, 45, 75);
    s.camera.look_at = Vec3(0, 0, 0);
    s.camera.fov_y_degrees = 50;
    return s;
}

struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::atomic<int64_t> bytes{0}, peak{0};
};

bool monitor(void* user, ssize_t bytes, bool) {
    auto* e = static_cast<EmbreeScene*>(user);
    const int64_t now = e->bytes += bytes;
    int64_t p = e->peak.load();
    while (now > p && !e->peak.compare_exchange_weak(p, now)) {
    }
    return true;
}

// Primary rays of a pinhole camera like Sheaf's (vertical field of view, square pixels).
Ray camera_ray(const Camera& c, int w, int h, int x, int y) {
    const Vec3 f = normalize(c.look_at - c.position);
    const Vec3 r = normalize(cross(f, c.up));
    const Vec3 u = cross(r, f);
    const float t = std::tan(c.fov_y_degrees * 0.5f * 3.14159265f / 180.0f);
    const float px = (2.0f * (float(x) + 0.5f) / float(w) - 1.0f) * t * float(w) / float(h);
    const float py = (1.0f - 2.0f * (float(y) + 0.5f) / float(h)) * t;
    Ray ray;
    ray.origin = c.position;
    ray.dir = normalize(f + r * px + u * py);
    ray.tmin = 0;
    ray.tmax = 1e30f;
    return ray;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<size_t> sizes = {10000, 100000, 1000000};
    int threads = 2, width = 512, rounds = 3;
    std::vector<std::string> modes = {"crsh", "bvh"};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
        if (a == "--sizes") {
            sizes.clear();
            for (const std::string& s : bench::split_list(next())) sizes.push_back(std::stoull(s));
        } else if (a == "--threads") {
            threads = std::max(1, std::stoi(next()));
        } else if (a == "--width") {
            width = std::max(8, std::stoi(next()));
        } else if (a == "--rounds") {
            rounds = std::max(1, std::stoi(next()));
        } else if (a == "--modes") {
            modes = bench::split_list(next());
        } else {
            std::printf("usage: sheaf_accel_bench [--sizes 10000,100000,1000000] [--threads 2] "
                        "[--width 512] [--modes crsh,bvh] [--rounds 3]\n");
            return a == "--help" || a == "-h" ? 0 : 2;
        }
    }
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    std::printf("threads %d, %dx%d, median of %d; shadow rays: the same rays for every "
                "column\n\n",
                threads, width, width, rounds);
    std::printf("| triangles | Embree build | Embree primary | Embree shadow | Embree B/tri | "
                "mode | Sheaf build | Sheaf shadow | of which traversal | ratio to Embree | Mrays/s | "
                "Sheaf B/tri | box tests / ray | exact tests / ray | frame | occluded (Sheaf / Embree) |\n");
    std::printf("|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    for (const size_t n : sizes) {
        const Scene scene = make_scene(n);
        const PreparedScene prepared = prepare_scene(scene);
        const size_t tris = prepared.tris.size();

        // Embree: one triangle geometry of the prepared triangles, built and cast.
        EmbreeScene e;
        const std::string config = "threads=" + std::to_string(threads);
        e.device = rtcNewDevice(config.c_str());
        rtcSetDeviceMemoryMonitorFunction(e.device, monitor, &e);
        std::vector<double> build_ms;
        for (int r = 0; r < rounds; ++r) {
            if (e.scene) rtcReleaseScene(e.scene);
            e.peak = e.bytes.load();
            const auto t0 = Clock::now();
            e.scene = rtcNewScene(e.device);
            RTCGeometry geom = rtcNewGeometry(e.device, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
                geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * tris));
            auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
                geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris));
            for (size_t t = 0; t < tris; ++t) {
                const TriangleVerts& tv = prepared.tris[t];
                for (int k = 0; k < 3; ++k) {
                    const Vec3 p = k == 0 ? tv.a : k == 1 ? tv.b : tv.c;
                    v[9 * t + 3 * size_t(k)] = p.x, v[9 * t + 3 * size_t(k) + 1] = p.y;
                    v[9 * t + 3 * size_t(k) + 2] = p.z;
                    idx[3 * t + size_t(k)] = unsigned(3 * t + size_t(k));
                }
            }
            rtcCommitGeometry(geom);
            rtcAttachGeometry(e.scene, geom);
            rtcReleaseGeometry(geom);
            rtcCommitScene(e.scene);
            build_ms.push_back(ms(t0, Clock::now()));
        }
        const double embree_bytes = double(e.peak.load());
        const int w = width, h = width;
        std::vector<RTCRayHit> prim(size_t(w) * size_t(h));
        std::vector<double> primary_ms;
        for (int r = 0; r < rounds; ++r) {
            const auto t0 = Clock::now();
            tbb::parallel_for(tbb::blocked_range<size_t>(0, prim.size(), 1024),
                              [&](const tbb::blocked_range<size_t>& br) {
                                  RTCIntersectContext ctx;
                                  rtcInitIntersectContext(&ctx);
                                  for (size_t i = br.begin(); i != br.end(); ++i) {
                                      const Ray cr = camera_ray(scene.camera, w, h, int(i % size_t(w)),
                                                                int(i / size_t(w)));
                                      RTCRayHit& rh = prim[i];
                                      rh.ray = {cr.origin.x, cr.origin.y, cr.origin.z, 0.0f,
                                                cr.dir.x,    cr.dir.y,    cr.dir.z,    0.0f,
                                                1e30f,       0xFFFFFFFFu, 0,           0};
                                      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                                      rtcIntersect1(e.scene, &ctx, &rh);
                                  }
                              });
            primary_ms.push_back(ms(t0, Clock::now()));
        }
        // The shadow rays: from every hit, offset along the normal, to the light.
        MemoryTracker mem;
        RayBatch shadows(RayType::Shadow, mem);
        std::vector<Ray> rays;
        for (size_t i = 0; i < prim.size(); ++i) {
            const RTCRayHit& rh = prim[i];
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
            const Vec3 o(rh.ray.org_x, rh.ray.org_y, rh.ray.org_z), d(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
            Vec3 nrm = normalize(Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
            if (dot(nrm, d) > 0) nrm = nrm * -1.0f;
            const Vec3 p = o + d * rh.ray.tfar + nrm * 1e-3f;
            Ray s;
            s.origin = p;
            s.dir = normalize(kLight - p);
            s.tmin = 0;
            s.tmax = length(kLight - p);
            rays.push_back(s);
        }
        shadows.resize(rays.size());
        for (size_t i = 0; i < rays.size(); ++i)
            shadows.rays[i] = rays[i], shadows.pixel[i] = uint32_t(i), shadows.light[i] = 0;
        std::vector<double> shadow_ms;
        size_t embree_occluded = 0;
        for (int r = 0; r < rounds; ++r) {
            std::vector<RTCRay> sr(rays.size());
            const auto t0 = Clock::now();
            tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 1024),
                              [&](const tbb::blocked_range<size_t>& br) {
                                  RTCIntersectContext ctx;
                                  rtcInitIntersectContext(&ctx);
                                  for (size_t i = br.begin(); i != br.end(); ++i) {
                                      const Ray& s = rays[i];
                                      sr[i] = {s.origin.x, s.origin.y, s.origin.z, s.tmin,
                                               s.dir.x,    s.dir.y,    s.dir.z,    0.0f,
                                               s.tmax,     0xFFFFFFFFu, 0,         0};
                                      rtcOccluded1(e.scene, &ctx, &sr[i]);
                                  }
                              });
            shadow_ms.push_back(ms(t0, Clock::now()));
            embree_occluded = 0;
            for (const RTCRay& x : sr) embree_occluded += x.tfar < 0 ? 1 : 0;
        }
        const double e_shadow = median(shadow_ms);
        for (const std::string& mode : modes) {
            Settings kv;
            kv.set("accel", mode);
            kv.set("width", std::to_string(w));
            kv.set("height", std::to_string(h));
            kv.set("threads", std::to_string(threads));
            const RenderSettings s = RenderSettings::resolve(kv);
            double build = 0, bytes = 0;
            if (s.accel == Accel::Bvh) {
                std::vector<double> b;
                Bvh tree;
                for (int r = 0; r < rounds; ++r) {
                    const auto t0 = Clock::now();
                    tree = build_bvh(prepared);
                    b.push_back(ms(t0, Clock::now()));
                }
                build = median(b);
                bytes = double(tree.bytes());
            } else {
                const auto t0 = Clock::now();
                const CullUnits units = make_cull_units(prepared, s.cull_objects ? s.cull_cluster : 0);
                build = ms(t0, Clock::now());
                bytes = double(units.count()) * (sizeof(Sphere) + 8);
            }
            std::vector<double> trace_ms, walk_ms;
            size_t occluded = 0;
            double box_tests = 0, exact_tests = 0; // per shadow ray
            const auto units = cull_units_for(prepared, s);
            for (int r = 0; r < rounds; ++r) {
                Stats st;
                TraceResult out;
                const auto t0 = Clock::now();
                trace_batch(prepared, *units, shadows, s, st, mem, out);
                trace_ms.push_back(ms(t0, Clock::now()));
                // The traversal alone (crsh: with its exact tests), without the tracer's
                // buffers, hashing, sorting and hierarchy.
                walk_ms.push_back(st.get("time_ms.traversal") + st.get("time_ms.final_tests"));
                occluded = size_t(std::count(out.occluded.begin(), out.occluded.end(), uint8_t(1)));
                box_tests = st.get("tests.shadow.nodes.tests") / double(rays.size());
                exact_tests = st.get("tests.shadow.final.tests") / double(rays.size());
            }
            std::vector<double> frame_ms;
            for (int r = 0; r < rounds; ++r) {
                const auto t0 = Clock::now();
                const Frame f = render_frame_cpu(prepared, s);
                frame_ms.push_back(ms(t0, Clock::now()));
            }
            const double t = median(trace_ms);
            std::printf("| %zu | %.1f ms | %.1f ms | %.1f ms | %.1f | %s | %.1f ms | %.1f ms | "
                        "%.1f ms | %.2f× | %.1f | %.1f | %.1f | %.1f | %.0f ms | %zu / %zu |\n",
                        tris, median(build_ms), median(primary_ms), e_shadow,
                        embree_bytes / double(tris), mode.c_str(), build, t, median(walk_ms),
                        t / e_shadow,
                        double(rays.size()) / t / 1e3, bytes / double(tris), box_tests,
                        exact_tests, median(frame_ms),
                        occluded, embree_occluded);
            std::fflush(stdout);
        }
        rtcReleaseScene(e.scene);
        rtcReleaseDevice(e.device);
    }
    return 0;
}
