// Object-space acceleration against Embree, side by side in one process: generated scenes of a
// terrain and 256 sphere meshes (real occlusion: the spheres shadow the terrain and each
// other), at several sizes. Embree casts the camera's primary rays (one per pixel); from every
// hit come a shadow ray to the light, 4 short ambient-occlusion rays and the mirror
// reflection, which Embree casts and Sheaf traces, the very same rays, under each accel mode
// (trace_batch, the frame pipeline's tracer); then Sheaf renders the whole frame under each
// mode. Build time, trace time per ray type, Mrays/s, structure bytes per triangle.
//
// Usage: sheaf_accel_bench [--sizes 10000,100000,1000000] [--threads 2] [--width 512]
//                          [--modes crsh,bvh] [--rounds 3] [--process embree|sheaf]
// Times are the median of the rounds. --process embree (or sheaf, under the last of --modes)
// runs one side alone on the first size, for that process's peak memory (/usr/bin/time -v). Embree 3 from Debian (libembree-dev) is a dependency of
// this benchmark only.
#include "bench_args.h"
#include "core/accel/bvh.h"
#include "core/accel/strips.h"
#include "core/frame/host_tracer.h"
#include "core/frame/render_frame.h"
#include "core/rsh/cull_units.h"

#include <embree3/rtcore.h>
#include <sys/resource.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
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
// (80 triangles each) standing on it: the terrain first, then the balls.
std::vector<Mesh> make_meshes(size_t tris) {
    std::vector<Mesh> out;
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
    out.push_back(std::move(m));
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
        out.push_back(std::move(sm));
    }
    return out;
}

// The scene of make_meshes, with the light and camera every run uses.
Scene make_scene(size_t tris) {
    Scene s;
    s.add_material(Material{});
    std::vector<Mesh> meshes = make_meshes(tris);
    for (size_t k = 0; k < meshes.size(); ++k)
        s.add_mesh_object(k == 0 ? std::string("terrain") : "ball" + std::to_string(k - 1),
                          std::move(meshes[k]), 0);
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

constexpr int kAo = 4;           // ambient-occlusion rays per hit
constexpr float kAoReach = 5.0f; // their length (the terrain is 100 wide, the balls 2-6)

// One set of secondary rays, as Sheaf traces them and as a list for Embree.
struct RaySet {
    RayType type;
    std::vector<Ray> rays;
    RayBatch batch;
};

// A float in [0, 1) from two integers (a hash; the same rays on every run).
float hash01(uint32_t a, uint32_t b) {
    uint32_t h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u;
    h ^= h >> 15, h *= 0x2C1B3C6Du, h ^= h >> 12, h *= 0x297A2D39u, h ^= h >> 15;
    return float(h >> 8) * (1.0f / 16777216.0f);
}

// The shadow, ambient-occlusion and reflection rays from every primary hit (Embree's), each
// origin offset along the normal turned towards the camera.
std::vector<RaySet> secondary_rays(const std::vector<RTCRayHit>& prim, MemoryTracker& mem) {
    std::vector<RaySet> sets;
    for (RayType t : {RayType::Shadow, RayType::Ao, RayType::Reflection})
        sets.push_back({t, {}, RayBatch(t, mem)});
    std::vector<uint32_t> pixel[3];
    for (size_t i = 0; i < prim.size(); ++i) {
        const RTCRayHit& rh = prim[i];
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
        const Vec3 o(rh.ray.org_x, rh.ray.org_y, rh.ray.org_z);
        const Vec3 d(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
        Vec3 nrm = normalize(Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
        if (dot(nrm, d) > 0) nrm = nrm * -1.0f;
        const Vec3 p = o + d * rh.ray.tfar + nrm * 1e-3f;
        Ray s;
        s.origin = p, s.tmin = 0;
        s.dir = normalize(kLight - p), s.tmax = length(kLight - p);
        sets[0].rays.push_back(s), pixel[0].push_back(uint32_t(i));
        // A frame around the normal for the hemisphere.
        const Vec3 a = std::fabs(nrm.x) > 0.5f ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
        const Vec3 tu = normalize(cross(a, nrm)), tv = cross(nrm, tu);
        for (int k = 0; k < kAo; ++k) {
            const float u1 = hash01(uint32_t(i), uint32_t(2 * k));
            const float u2 = hash01(uint32_t(i), uint32_t(2 * k + 1));
            const float r = std::sqrt(u1), phi = 6.2831853f * u2;
            Ray ao;
            ao.origin = p, ao.tmin = 0, ao.tmax = kAoReach;
            ao.dir = normalize(tu * (r * std::cos(phi)) + tv * (r * std::sin(phi)) +
                               nrm * std::sqrt(std::max(0.0f, 1.0f - u1)));
            sets[1].rays.push_back(ao), pixel[1].push_back(uint32_t(i));
        }
        Ray m;
        m.origin = p, m.tmin = 0, m.tmax = 1e30f;
        m.dir = normalize(d - nrm * (2.0f * dot(d, nrm)));
        sets[2].rays.push_back(m), pixel[2].push_back(uint32_t(i));
    }
    for (size_t k = 0; k < sets.size(); ++k) {
        RayBatch& b = sets[k].batch;
        b.resize(sets[k].rays.size());
        for (size_t i = 0; i < sets[k].rays.size(); ++i)
            b.rays[i] = sets[k].rays[i], b.pixel[i] = pixel[k][i];
        if (b.type == RayType::Shadow) std::fill(b.light.begin(), b.light.end(), 0u);
    }
    return sets;
}

// --process embree: what an application of Embree holds for the scene of `n` triangles, in a
// process of its own (for its peak memory: /usr/bin/time -v): its meshes, handed to Embree as
// one geometry (shared vertices, 32-bit indices), the scene built, the camera's rays and a
// shadow ray from every hit cast.
int embree_process(size_t n, int threads, int width) {
    std::vector<Mesh> meshes = make_meshes(n);
    size_t verts = 0, tris = 0;
    for (const Mesh& m : meshes) verts += m.positions.size(), tris += m.triangle_count();
    const std::string config = "threads=" + std::to_string(threads);
    RTCDevice device = rtcNewDevice(config.c_str());
    const auto t0 = Clock::now();
    RTCScene scene = rtcNewScene(device);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), verts));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris));
    size_t vb = 0, ib = 0;
    for (const Mesh& m : meshes) {
        for (const Vec3& p : m.positions) v[vb * 3] = p.x, v[vb * 3 + 1] = p.y, v[vb * 3 + 2] = p.z, ++vb;
        const size_t base = vb - m.positions.size();
        for (uint32_t i : m.indices) idx[ib++] = unsigned(base + i);
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene);
    const double build = ms(t0, Clock::now());
    Camera cam;
    cam.position = Vec3(0, 45, 75), cam.look_at = Vec3(0, 0, 0), cam.fov_y_degrees = 50;
    std::atomic<size_t> occluded{0};
    const auto t1 = Clock::now();
    tbb::parallel_for(tbb::blocked_range<size_t>(0, size_t(width) * size_t(width), 1024),
                      [&](const tbb::blocked_range<size_t>& br) {
                          RTCIntersectContext ctx;
                          rtcInitIntersectContext(&ctx);
                          size_t found = 0;
                          for (size_t i = br.begin(); i != br.end(); ++i) {
                              const Ray cr = camera_ray(cam, width, width, int(i % size_t(width)),
                                                        int(i / size_t(width)));
                              RTCRayHit rh;
                              rh.ray = {cr.origin.x, cr.origin.y, cr.origin.z, 0.0f,
                                        cr.dir.x,    cr.dir.y,    cr.dir.z,    0.0f,
                                        1e30f,       0xFFFFFFFFu, 0,           0};
                              rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                              rtcIntersect1(scene, &ctx, &rh);
                              if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
                              Vec3 nrm = normalize(Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
                              if (dot(nrm, cr.dir) > 0) nrm = nrm * -1.0f;
                              const Vec3 p = cr.origin + cr.dir * rh.ray.tfar + nrm * 1e-3f;
                              const Vec3 d = normalize(kLight - p);
                              RTCRay sr = {p.x, p.y, p.z, 0.0f, d.x, d.y, d.z, 0.0f,
                                           length(kLight - p), 0xFFFFFFFFu, 0, 0};
                              rtcOccluded1(scene, &ctx, &sr);
                              found += sr.tfar < 0 ? 1 : 0;
                          }
                          occluded += found;
                      });
    std::printf("embree process: %zu triangles, build %.1f ms, primary and shadow rays %.1f ms, "
                "%zu occluded\n",
                tris, build, ms(t1, Clock::now()), occluded.load());
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return 0;
}

// --process sheaf: the same scene rendered by Sheaf under `mode`, in a process of its own:
// prepared, its structure built, one frame at width x width.
// The process's peak resident memory so far, in MiB.
double peak_mib() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss) / 1024.0;
}

int sheaf_process(size_t n, int threads, int width, const std::string& mode) {
    const auto t0 = Clock::now();
    const double start = peak_mib();
    std::optional<Scene> scene(make_scene(n));
    const double made = peak_mib();
    const PreparedScene prepared = prepare_scene(*scene);
    const double ready = peak_mib();
    scene.reset();
    Settings kv;
    kv.set("accel", mode);
    kv.set("width", std::to_string(width));
    kv.set("height", std::to_string(width));
    kv.set("threads", std::to_string(threads));
    const RenderSettings s = RenderSettings::resolve(kv);
    const auto units = cull_units_for(prepared, s);
    const double built = peak_mib();
    const Frame f = render_frame_cpu(prepared, s);
    std::printf("sheaf process: %zu triangles, accel=%s, scene and frame %.1f ms (frame %.1f ms), "
                "peak tracked %.1f MiB; peak resident: at start %.0f MiB, scene made %.0f, "
                "prepared %.0f, structure built %.0f, after the frame %.0f\n",
                prepared.tris.size(), mode.c_str(), ms(t0, Clock::now()),
                f.stats.get("time_ms.frame"), f.stats.get("memory.peak_bytes") / 1048576.0, start,
                made, ready, built, peak_mib());
    return 0;
}

} // namespace

int run(int argc, char** argv) {
    std::vector<size_t> sizes = {10000, 100000, 1000000};
    int threads = 2, width = 512, rounds = 3;
    std::vector<std::string> modes = {"crsh", "bvh"};
    std::string process; // embree or sheaf: one side alone, for its process's peak memory
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
        if (a == "--sizes") {
            sizes.clear();
            for (const std::string& s : bench::split_list(next())) {
                if (s.find_first_not_of("0123456789") != std::string::npos) {
                    std::fprintf(stderr, "sheaf_accel_bench: --sizes: '%s' is not a count\n",
                                 s.c_str());
                    return 2;
                }
                sizes.push_back(std::stoull(s));
            }
        } else if (a == "--threads") {
            threads = std::max(1, std::stoi(next()));
        } else if (a == "--width") {
            width = std::max(8, std::stoi(next()));
        } else if (a == "--rounds") {
            rounds = std::max(1, std::stoi(next()));
        } else if (a == "--modes") {
            modes = bench::split_list(next());
        } else if (a == "--process") {
            process = next();
        } else {
            std::printf("usage: sheaf_accel_bench [--sizes 10000,100000,1000000] [--threads 2] "
                        "[--width 512] [--modes crsh,bvh] [--rounds 3] [--process embree|sheaf]\n");
            return a == "--help" || a == "-h" ? 0 : 2;
        }
    }
    if (sizes.empty() || modes.empty()) {
        std::fprintf(stderr, "sheaf_accel_bench: --sizes and --modes need at least one value\n");
        return 2;
    }
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    if (process == "embree") return embree_process(sizes.at(0), threads, width);
    if (process == "sheaf") return sheaf_process(sizes.at(0), threads, width, modes.back());
    if (!process.empty()) {
        std::fprintf(stderr, "--process takes embree or sheaf, not '%s'\n", process.c_str());
        return 2;
    }
    std::printf("threads %d, %dx%d, median of %d; the same rays of each type for Embree and "
                "every mode; the primary rays Embree's\n\n",
                threads, width, width, rounds);
    std::printf("| triangles | rays | count | Embree build | Embree trace | mode | Sheaf build | "
                "Sheaf trace | of which traversal | ratio to Embree | Mrays/s | Sheaf B/tri | box "
                "tests / ray | sphere tests / ray | exact tests / ray | frame | occluded or hit "
                "(Sheaf / Embree) |\n");
    std::printf(
        "|---:|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    struct Summary {
        size_t tris;
        double embree_bytes, primary_ms;
    };
    std::vector<Summary> summary;
    struct Footprint {
        size_t tris;
        double bvh_hierarchy, list_geometry, strips_hierarchy, strips_geometry;
        size_t strips, joins, loose;
    };
    std::vector<Footprint> footprint;
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
        // From every hit, offset along the normal: a shadow ray to the light, kAo ambient
        // occlusion rays (cosine-weighted over the hemisphere, reaching kAoReach) and the
        // mirror reflection (closest hit).
        MemoryTracker mem;
        const auto sets = secondary_rays(prim, mem);
        // Embree casts each set; any-hit sets count the occluded rays, the reflection set the
        // rays that hit something.
        std::vector<double> embree_ms(sets.size());
        std::vector<size_t> embree_found(sets.size());
        for (size_t k = 0; k < sets.size(); ++k) {
            const std::vector<Ray>& rays = sets[k].rays;
            const bool any = sets[k].type != RayType::Reflection;
            std::vector<double> t;
            std::vector<RTCRayHit> rh(rays.size());
            for (int r = 0; r < rounds; ++r) {
                const auto t0 = Clock::now();
                tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 1024),
                                  [&](const tbb::blocked_range<size_t>& br) {
                                      RTCIntersectContext ctx;
                                      rtcInitIntersectContext(&ctx);
                                      for (size_t i = br.begin(); i != br.end(); ++i) {
                                          const Ray& s = rays[i];
                                          rh[i].ray = {s.origin.x, s.origin.y,  s.origin.z, s.tmin,
                                                       s.dir.x,    s.dir.y,     s.dir.z,    0.0f,
                                                       s.tmax,     0xFFFFFFFFu, 0,          0};
                                          rh[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
                                          if (any)
                                              rtcOccluded1(e.scene, &ctx, &rh[i].ray);
                                          else
                                              rtcIntersect1(e.scene, &ctx, &rh[i]);
                                      }
                                  });
                t.push_back(ms(t0, Clock::now()));
            }
            embree_ms[k] = median(t);
            size_t found = 0;
            for (const RTCRayHit& x : rh)
                found += any ? (x.ray.tfar < 0 ? 1 : 0)
                             : (x.hit.geomID != RTC_INVALID_GEOMETRY_ID ? 1 : 0);
            embree_found[k] = found;
        }
        {
            // Bytes a triangle, hierarchy and geometry apart (paper 004, Table 1): the BVH over
            // the scene's triangle list (36 bytes a triangle, three corners), and the strips
            // with their own vertices, indices and primitive ids.
            const Bvh tree = build_bvh(prepared);
            const Strips strips = build_strips(prepared);
            const double t = double(tris);
            footprint.push_back({tris, double(tree.bytes()) / t, double(sizeof(TriangleVerts)),
                                 double(strips.hierarchy_bytes()) / t,
                                 double(strips.geometry_bytes()) / t, strips.strips.size(),
                                 strips.joins, strips.loose});
        }
        summary.push_back({tris, embree_bytes / double(tris), median(primary_ms)});
        for (const std::string& mode : modes) {
            Settings kv;
            kv.set("accel", mode);
            kv.set("width", std::to_string(w));
            kv.set("height", std::to_string(h));
            kv.set("threads", std::to_string(threads));
            const RenderSettings s = RenderSettings::resolve(kv);
            double build = 0, bytes = 0;
            if (uses_bvh(s.accel)) {
                std::vector<double> b;
                Bvh tree;
                for (int r = 0; r < rounds; ++r) {
                    const auto t0 = Clock::now();
                    tree = build_bvh(prepared);
                    b.push_back(ms(t0, Clock::now()));
                }
                build = median(b);
                bytes = double(tree.bytes());
            } else if (s.accel == Accel::Strips) {
                std::vector<double> b;
                Strips strips;
                for (int r = 0; r < rounds; ++r) {
                    const auto t0 = Clock::now();
                    strips = build_strips(prepared);
                    b.push_back(ms(t0, Clock::now()));
                }
                build = median(b);
                bytes = double(strips.hierarchy_bytes() + strips.geometry_bytes());
            } else {
                const auto t0 = Clock::now();
                const CullUnits units = make_cull_units(prepared, s.cull_objects ? s.cull_cluster : 0);
                build = ms(t0, Clock::now());
                bytes = double(units.count()) * (sizeof(Sphere) + 8);
            }
            const auto units = cull_units_for(prepared, s);
            std::vector<double> frame_ms;
            for (int r = 0; r < rounds; ++r) {
                const auto t0 = Clock::now();
                const Frame f = render_frame_cpu(prepared, s);
                frame_ms.push_back(ms(t0, Clock::now()));
            }
            for (size_t k = 0; k < sets.size(); ++k) {
                const RayBatch& batch = sets[k].batch;
                const std::string p = std::string("tests.") + ray_type_name(batch.type) + ".";
                std::vector<double> trace_ms, walk_ms;
                size_t found = 0;
                double box_tests = 0, sphere_tests = 0, exact_tests = 0; // per ray
                const double n_rays = double(sets[k].rays.size());
                for (int r = 0; r < rounds; ++r) {
                    Stats st;
                    TraceResult out;
                    const auto t0 = Clock::now();
                    trace_batch(prepared, *units, batch, s, st, mem, out);
                    trace_ms.push_back(ms(t0, Clock::now()));
                    // The traversal alone (with its exact tests), without the tracer's
                    // buffers, hashing, sorting and hierarchy.
                    walk_ms.push_back(st.get("time_ms.traversal") + st.get("time_ms.final_tests"));
                    found = batch.type == RayType::Reflection
                                ? size_t(std::count_if(out.closest.begin(), out.closest.end(),
                                                       [](uint64_t c) { return c != kNoHit; }))
                                : size_t(std::count(out.occluded.begin(), out.occluded.end(),
                                                    uint8_t(1)));
                    box_tests = st.get(p + "nodes.tests") / n_rays;
                    exact_tests = st.get(p + "final.tests") / n_rays;
                    // The ray hierarchy's node tests: against object and unit spheres (or the
                    // BVH's child spheres), then level by level.
                    double spheres = st.get(p + "objects.tests");
                    for (int l = 1; l <= s.hierarchy_depth; ++l)
                        spheres += st.get(p + "level" + std::to_string(l) + ".tests");
                    sphere_tests = spheres / n_rays;
                }
                const double t = median(trace_ms);
                std::printf("| %zu | %s | %zu | %.1f ms | %.1f ms | %s | %.1f ms | %.1f ms | "
                            "%.1f ms | %.2f× | %.1f | %.1f | %.1f | %.1f | %.1f | %.0f ms | "
                            "%zu / %zu |\n",
                            tris, ray_type_name(batch.type), sets[k].rays.size(), median(build_ms),
                            embree_ms[k], mode.c_str(), build, t, median(walk_ms), t / embree_ms[k],
                            n_rays / t / 1e3, bytes / double(tris), box_tests, sphere_tests,
                            exact_tests, median(frame_ms), found, embree_found[k]);
                std::fflush(stdout);
            }
        }
        rtcReleaseScene(e.scene);
        rtcReleaseDevice(e.device);
    }
    std::printf("\nEmbree's whole scene (its memory monitor's peak) and its primary rays:\n\n"
                "| triangles | Embree B/tri | Embree primary |\n|---:|---:|---:|\n");
    for (const Summary& x : summary)
        std::printf("| %zu | %.1f | %.1f ms |\n", x.tris, x.embree_bytes, x.primary_ms);
    std::printf("\nBytes a triangle, hierarchy + geometry (the triangle list: three corners a "
                "triangle, as the scene keeps them):\n\n| triangles | bvh | triangle list | bvh "
                "all | strips | strips geometry | strips all | strips | joins | triangles in no "
                "strip |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const Footprint& x : footprint)
        std::printf("| %zu | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %zu | %zu | %zu |\n", x.tris,
                    x.bvh_hierarchy, x.list_geometry, x.bvh_hierarchy + x.list_geometry,
                    x.strips_hierarchy, x.strips_geometry, x.strips_hierarchy + x.strips_geometry,
                    x.strips, x.joins, x.loose);
    return 0;
}

int main(int argc, char** argv) {
    // A bad size or setting is an error message, not an abort.
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sheaf_accel_bench: %s\n", e.what());
        return 2;
    }
}
