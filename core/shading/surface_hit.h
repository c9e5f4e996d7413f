// The surface at a hit: position, normals, material (texture maps resolved), colour, filter,
// transmit and the shading normal a normal pattern tilts. Host-and-device: both backends
// and the wavefront pipeline rebuild every primary and bounce hit with it.
#pragma once

#include "core/geometry/ray.h"
#include "core/math/hd_math.h"
#include "core/scene/analytic.h"
#include "core/shading/surface.h"
#include "core/shading/surface_texture.h"

namespace sheaf {

namespace surface_detail {

// The surface's material (its inside one from behind, texture maps resolved), shading normal,
// colour, filter and transmit at h.position; (uv_s, uv_t) are its texture coordinates. As in
// POV-Ray, texture maps see the surface's normal and the pigment the one its normal pattern
// tilted (slope patterns).
SHEAF_HD_NOINLINE void finish_surface(const SceneView& scene, SurfaceHit& h, float uv_s, float uv_t) {
    h.light_group = scene.materials[h.material].light_group; // the object's, as placed
    if (!h.front && scene.materials[h.material].inside >= 0)
        h.material = uint32_t(scene.materials[h.material].inside); // seen from inside
    h.material = resolve_material(scene, h.material, h.position, h.normal, uv_s, uv_t);
    const Material& m = scene.materials[h.material];
    if (m.normal >= 0) {
        // As in POV-Ray, a normal tilted past the surface stays as tilted (it faces away from
        // the lights and the eye, so that point is shaded dark).
        h.normal = perturb_normal(scene, uint32_t(m.normal), h.position, h.normal);
    }
    if (m.pigment >= 0) {
        const SurfaceColor c =
            evaluate_pigment(scene, uint32_t(m.pigment), h.position, uv_s, uv_t, h.normal);
        h.albedo = c.rgb;
        h.filter = c.filter;
        h.transmit = c.transmit;
    } else {
        h.albedo = m.color;
        h.filter = m.transmission;
        h.transmit = 0;
        if (m.texture >= 0 && scene.sampler)
            h.albedo = m.color * texture_detail::sample_image(scene, m.texture, h.position, uv_s,
                                                              uv_t);
    }
}

// An analytic primitive's surface: the exact test again gives the normal and the leaf (and so
// the material) of the surface at t.
SHEAF_HD_INLINE SurfaceHit analytic_surface_hit(const SceneView& scene, const Ray& ray,
                                                uint32_t prim, float t) {
    SurfaceHit h;
    h.prim = prim;
    h.t = t;
    h.incoming = ray.dir;
    h.position = ray_at(ray, t);
    AnalyticHit a;
    Ray r = ray;
    r.tmax = nextafterf(t, INFINITY);
    Vec3 n(0, 0, 1);
    if (analytic_first_hit(scene, prim - scene.tri_count, r, a)) {
        n = a.normal;
        h.material = scene.shape_material[a.leaf];
    } else {
        h.material = scene.object_material[scene.prim_object[prim]];
    }
    h.front = dot(n, ray.dir) < 0;
    if (!h.front) n = -n;
    h.geo_normal = h.normal = n;
    // Analytic shapes have no texture coordinates of their own: planar (x, y) in world space.
    finish_surface(scene, h, h.position.x, h.position.y);
    return h;
}

} // namespace surface_detail

/// Rebuilds the surface at the intersection of `ray` with primitive `prim` at distance t.
/// Barycentrics come from the triangle's plane, clamped inside it, so a pixel whose centre
/// grazes an edge still gets a normal from the triangle.
SHEAF_HD_INLINE SurfaceHit make_surface_hit(const SceneView& scene, const Ray& ray, uint32_t prim,
                                            float t) {
    if (!scene.is_triangle(prim)) return surface_detail::analytic_surface_hit(scene, ray, prim, t);
    const TriangleVerts& tv = scene.tris[prim];
    const Vec3 e1 = tv.b - tv.a, e2 = tv.c - tv.a;
    Vec3 gn = normalize(cross(e1, e2));
    SurfaceHit h;
    h.prim = prim;
    h.material = scene.object_material[scene.prim_object[prim]];
    h.t = t;
    h.incoming = ray.dir;
    h.position = ray_at(ray, t);

    // Barycentrics of the hit point in the triangle's plane, clamped to the triangle.
    const Vec3 p = h.position - tv.a;
    const float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
    const float d20 = dot(p, e1), d21 = dot(p, e2);
    const float den = d00 * d11 - d01 * d01;
    float u = den != 0 ? (d11 * d20 - d01 * d21) / den : 0.0f;
    float v = den != 0 ? (d00 * d21 - d01 * d20) / den : 0.0f;
    u = hdm::fminf(hdm::fmaxf(u, 0.0f), 1.0f);
    v = hdm::fminf(hdm::fmaxf(v, 0.0f), 1.0f - u);

    h.front = dot(gn, ray.dir) < 0;
    if (!h.front) gn = -gn;
    h.geo_normal = gn;
    // Vertex normals and texture coordinates: none in the scene when no mesh has them.
    Vec3 n = gn;
    if (scene.normals) {
        const TriangleNormals& tn = scene.normals[prim];
        if (tn.na.x != 0 || tn.na.y != 0 || tn.na.z != 0) {
            n = normalize(tn.na * (1.0f - u - v) + tn.nb * u + tn.nc * v);
            if (dot(n, gn) < 0) n = -n; // an interpolated normal on the far side is turned round
            if (length_squared(n) == 0) n = gn;
        }
    }
    h.normal = n;
    float uv_s = 0, uv_t = 0;
    if (scene.uvs) {
        const TriangleUvs& tu = scene.uvs[prim];
        const float w = 1.0f - u - v;
        uv_s = w * tu.s[0] + u * tu.s[1] + v * tu.s[2];
        uv_t = w * tu.t[0] + u * tu.t[1] + v * tu.t[2];
    }
    surface_detail::finish_surface(scene, h, uv_s, uv_t);
    return h;
}

} // namespace sheaf
