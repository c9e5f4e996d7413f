#include "core/geometry/blob_build.h"

#include <algorithm>
#include <cmath>

namespace sheaf {

namespace {

/// The component whose unit space `unit_to_blob` places, reaching `len` along its z axis.
void add_element(BlobModel& b, const Affine& unit_to_blob, float len, float strength) {
    if (!std::isfinite(strength)) throw BlobError("a blob component's strength is not finite");
    if (!unit_to_blob.finite()) throw BlobError("a blob component's placement is not finite");
    if (!(std::fabs(unit_to_blob.determinant()) >= 1e-20f))
        throw BlobError("a blob component is flattened to nothing by its transforms");
    BlobElement e;
    e.to_unit = unit_to_blob.inverse();
    e.strength = strength;
    e.len = len;
    const Vec3 c = unit_to_blob.point(Vec3(0, 0, 0.5f * len));
    e.bound[0] = c.x, e.bound[1] = c.y, e.bound[2] = c.z;
    e.bound[3] = unit_to_blob.max_scale() * (1 + 0.5f * len) * (1 + 1e-5f);
    b.elements.push_back(e);
}

void check_radius(float radius) {
    if (!(radius > 0) || !std::isfinite(radius))
        throw BlobError("a blob component's radius must be a positive number");
}

} // namespace

void add_blob_sphere(BlobModel& b, Vec3 centre, float radius, float strength,
                     const Affine& placement) {
    check_radius(radius);
    add_element(b, placement * Affine::translate(centre) * Affine::scale(Vec3(radius)), 0,
                strength);
}

void add_blob_cylinder(BlobModel& b, Vec3 base, Vec3 end, float radius, float strength,
                       const Affine& placement) {
    check_radius(radius);
    const Vec3 axis = end - base;
    const float length = std::sqrt(dot(axis, axis));
    if (!std::isfinite(length)) throw BlobError("a blob cylinder's end points are not finite");
    if (!(length > 1e-6f * radius)) return add_blob_sphere(b, base, radius, strength, placement);
    // A frame whose z runs along the axis, scaled by the radius.
    const Vec3 w = axis / length;
    const Vec3 a = std::fabs(w.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = normalize(cross(a, w)), v = cross(w, u);
    Affine f;
    for (int i = 0; i < 3; ++i)
        f.m[i][0] = u[i] * radius, f.m[i][1] = v[i] * radius, f.m[i][2] = w[i] * radius,
        f.m[i][3] = base[i];
    add_element(b, placement * f, length / radius, strength);
}

bool blob_box(const BlobModel& b, Vec3& lo, Vec3& hi) {
    lo = Vec3(INFINITY), hi = Vec3(-INFINITY);
    for (const BlobElement& e : b.elements) {
        if (!(e.strength > 0)) continue;
        const Vec3 c(e.bound[0], e.bound[1], e.bound[2]);
        lo = vmin(lo, c - Vec3(e.bound[3])), hi = vmax(hi, c + Vec3(e.bound[3]));
    }
    return lo.x <= hi.x;
}

void blob_bound(const BlobModel& b, float bound[4]) {
    Vec3 lo, hi;
    if (!blob_box(b, lo, hi)) {
        bound[0] = bound[1] = bound[2] = bound[3] = 0;
        return;
    }
    const Vec3 c = (lo + hi) * 0.5f;
    float r = 0;
    for (const BlobElement& e : b.elements)
        if (e.strength > 0)
            r = std::max(r, length(Vec3(e.bound[0], e.bound[1], e.bound[2]) - c) + e.bound[3]);
    bound[0] = c.x, bound[1] = c.y, bound[2] = c.z, bound[3] = r * (1 + 1e-6f);
}

} // namespace sheaf
