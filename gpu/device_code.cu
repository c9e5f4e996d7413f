// Device instances of the shared per-element functions (SHEAF_HD in the core headers): the
// geometry tests, the node unions, the hashes and the shading terms. Compiling this file with
// nvcc is what keeps "one source for CPU and CUDA" true while the CUDA backend grows.
#include "core/geometry/cone_sphere.h"
#include "core/geometry/min_sphere.h"
#include "core/geometry/ray_triangle.h"
#include "core/geometry/shape.h"
#include "core/hash/ray_hash.h"
#include "core/raster/camera.h"
#include "core/rsh/trace.h"
#include "core/shading/shade.h"
#include "core/texture/pattern_eval.h"

namespace sheaf {

__global__ void device_code_instances(const Ray* rays, const TriangleVerts* tris,
                                      const Sphere* spheres, const Cone* cones, int n,
                                      uint32_t* keys, uint64_t* hits, Vec3* color,
                                      CameraFrame cam) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    const Ray r = i == 0 ? cam.pixel_ray(0, 0) : rays[i];
    TriangleHit h;
    hits[i] = intersect_triangle(r, tris[i].a, tris[i].b, tris[i].c, h) ? pack_hit(h.t, uint32_t(i))
                                                                        : kNoHit;
    const RayNode node = make_ray_node(sphere_union(spheres, 2), cone_union(cones, 2));
    const Sphere ts = triangle_sphere(tris[i].a, tris[i].b, tris[i].c);
    Aabb box{Vec3(0.0f), Vec3(1.0f)};
    uint32_t k192[6];
    hash192_key(box, r.origin, r.dir, k192);
    keys[i] = (node_hits_sphere(node, ts) ? 1u : 0u) ^ crsh_shadow_key(1, 2, r.dir) ^
              crsh_secondary_key(box, r.origin, r.dir) ^ hash32_key(box, r.origin, r.dir) ^ k192[5];
    Material m;
    Vec3 out;
    const float kr = fresnel_dielectric(0.5f, 1.0f / 1.5f);
    if (refract(r.dir, Vec3(0, 0, 1), 1.0f / 1.5f, out)) color[i] = out * kr;
    SurfaceHit sh;
    sh.normal = sh.geo_normal = Vec3(0, 0, 1);
    sh.incoming = r.dir;
    sh.albedo = m.color;
    color[i] += direct_light(m, sh, Vec3(0, 0, 1), Vec3(1.0f)) + ambient_light(m, sh) +
                interior_fade(m, 1.0f) + mirror_weight(m, sh);
    const Vec3 q = pattern_point(Pattern{}, r.origin, nullptr);
    color[i] += Vec3(pattern_value_at(Pattern{}, q) + float(pattern_index_at(Pattern{}, q)));
    Span spans[kMaxShapeSpans];
    const Shape shape{ShapeKind(i % 7), 0.3f, 0.5f, (i & 8) != 0};
    PlacedShape placed{shape, Affine(), Affine()};
    if (shape_spans(shape, to_local_ray(placed, r), spans) > 0) color[i] += normal_to_world(placed, spans[0].n0);
    (void)sphere_union_paper(spheres[0], spheres[1]);
    (void)cone_union_paper(cones[0], cones[1]);
}

} // namespace sheaf
