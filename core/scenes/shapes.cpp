// Mesh builders for the built-in scenes (see shapes.h).
#include "core/scenes/shapes.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sheaf {

namespace {

/// Two unit vectors u, w perpendicular to unit `a` with cross(u, w) = a.
void frame(Vec3 a, Vec3& u, Vec3& w) {
    const Vec3 helper = std::fabs(a.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    u = normalize(cross(helper, a));
    w = cross(a, u);
}

/// The cosine and sine of step i of n around a full turn, exact at the quarter turns.
std::pair<float, float> turn(int i, int n) {
    const float t = 2.0f * kPi * float(i % n) / float(n);
    return {std::cos(t), std::sin(t)};
}

void add_triangle(Mesh& m, uint32_t a, uint32_t b, uint32_t c) {
    // Collapsed triangles (at poles and cone tips) carry no surface.
    if (m.positions[a] == m.positions[b] || m.positions[b] == m.positions[c] ||
        m.positions[a] == m.positions[c])
        return;
    m.indices.insert(m.indices.end(), {a, b, c});
}

/// Appends a grid of cu x cv vertices from vertex(i, j) -> {position, normal} and its cells
/// as triangles; wrapping closes the grid in u or v. cross(dP/du, dP/dv) must point outward.
template <class VertexFn>
void append_grid(Mesh& m, int cu, int cv, bool wrap_u, bool wrap_v, VertexFn vertex) {
    const uint32_t base = uint32_t(m.positions.size());
    for (int j = 0; j < cv; ++j) {
        for (int i = 0; i < cu; ++i) {
            const auto [p, n] = vertex(i, j);
            m.positions.push_back(p);
            m.normals.push_back(n);
        }
    }
    auto at = [&](int i, int j) { return base + uint32_t((j % cv) * cu + (i % cu)); };
    const int cells_u = wrap_u ? cu : cu - 1, cells_v = wrap_v ? cv : cv - 1;
    for (int j = 0; j < cells_v; ++j) {
        for (int i = 0; i < cells_u; ++i) {
            const uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            add_triangle(m, a, b, c);
            add_triangle(m, a, c, d);
        }
    }
}

/// A flat disk facing `n` (unit), as a fan of `segments` triangles.
void append_disk(Mesh& m, Vec3 center, Vec3 n, float radius, int segments) {
    Vec3 u, w;
    frame(n, u, w);
    const uint32_t c = uint32_t(m.positions.size());
    m.positions.push_back(center);
    m.normals.push_back(n);
    for (int i = 0; i < segments; ++i) {
        const auto [cs, sn] = turn(i, segments);
        m.positions.push_back(center + (u * cs + w * sn) * radius);
        m.normals.push_back(n);
    }
    for (int i = 0; i < segments; ++i)
        add_triangle(m, c, c + 1 + uint32_t(i), c + 1 + uint32_t((i + 1) % segments));
}

void append_quad(Mesh& m, Vec3 corner, Vec3 edge_u, Vec3 edge_v, int nu, int nv) {
    const Vec3 n = normalize(cross(edge_u, edge_v));
    append_grid(m, nu + 1, nv + 1, false, false, [&](int i, int j) {
        return std::pair{corner + edge_u * (float(i) / float(nu)) + edge_v * (float(j) / float(nv)),
                         n};
    });
}

} // namespace

Mesh make_quad(Vec3 corner, Vec3 edge_u, Vec3 edge_v, int nu, int nv) {
    Mesh m;
    append_quad(m, corner, edge_u, edge_v, std::max(nu, 1), std::max(nv, 1));
    return m;
}

Mesh make_box(Vec3 lo, Vec3 hi) {
    const Vec3 s = hi - lo;
    const Vec3 x(s.x, 0, 0), y(0, s.y, 0), z(0, 0, s.z);
    Mesh m;
    append_quad(m, Vec3(hi.x, lo.y, lo.z), y, z, 1, 1); // +x
    append_quad(m, lo, z, y, 1, 1);                     // -x
    append_quad(m, Vec3(lo.x, hi.y, lo.z), z, x, 1, 1); // +y
    append_quad(m, lo, x, z, 1, 1);                     // -y
    append_quad(m, Vec3(lo.x, lo.y, hi.z), x, y, 1, 1); // +z
    append_quad(m, lo, y, x, 1, 1);                     // -z
    return m;
}

Mesh make_lathe(Vec3 base, Vec3 axis_dir, const std::vector<ProfilePoint>& profile, int segments) {
    Mesh m;
    const int k = int(profile.size());
    if (k < 2 || segments < 3) return m;
    const Vec3 a = normalize(axis_dir);
    Vec3 u, w;
    frame(a, u, w);
    // The normal of each profile point, in (radial, axial) terms: the mean of its two spans'.
    std::vector<std::pair<float, float>> pn(size_t(k), {0.0f, 0.0f});
    for (int s = 0; s + 1 < k; ++s) {
        const float dr = profile[s + 1].radius - profile[s].radius;
        const float dh = profile[s + 1].height - profile[s].height;
        const float l = std::sqrt(dr * dr + dh * dh);
        if (l <= 0) continue;
        for (int e : {s, s + 1}) pn[e].first += dh / l, pn[e].second -= dr / l;
    }
    append_grid(m, segments, k, true, false, [&](int i, int j) {
        const auto [cs, sn] = turn(i, segments);
        const Vec3 radial = u * cs + w * sn;
        const Vec3 p = base + a * profile[j].height + radial * profile[j].radius;
        Vec3 n = normalize(radial * pn[j].first + a * pn[j].second);
        if (length_squared(n) == 0) n = radial;
        return std::pair{p, n};
    });
    return m;
}

Mesh make_cone(Vec3 base, Vec3 top, float base_radius, float top_radius, int segments, bool caps) {
    const Vec3 axis = top - base;
    const float h = length(axis);
    Mesh m = make_lathe(base, axis, {{base_radius, 0.0f}, {top_radius, h}}, segments);
    if (caps) {
        const Vec3 a = normalize(axis);
        if (base_radius > 0) append_disk(m, base, -a, base_radius, segments);
        if (top_radius > 0) append_disk(m, top, a, top_radius, segments);
    }
    return m;
}

Mesh make_cylinder(Vec3 base, Vec3 top, float radius, int segments, bool caps) {
    return make_cone(base, top, radius, radius, segments, caps);
}

Mesh make_uv_sphere(Vec3 center, float radius, int stacks, int slices) {
    Mesh m;
    append_grid(m, slices, stacks + 1, true, false, [&](int i, int j) {
        const float phi = kPi * float(j) / float(stacks);
        // Exact poles, so that the collapsed triangles there are recognised and dropped.
        const float sp = (j == 0 || j == stacks) ? 0.0f : std::sin(phi);
        const float cp = j == 0 ? 1.0f : (j == stacks ? -1.0f : std::cos(phi));
        const auto [ct, st] = turn(i, slices);
        const Vec3 n(sp * ct, cp, sp * st);
        return std::pair{center + n * radius, n};
    });
    return m;
}

Mesh make_torus(Vec3 center, Vec3 axis, float major_radius, float minor_radius, int major_segments,
                int minor_segments) {
    const Vec3 a = normalize(axis);
    Vec3 u, w;
    frame(a, u, w);
    Mesh m;
    append_grid(m, major_segments, minor_segments, true, true, [&](int i, int j) {
        const auto [ct, st] = turn(i, major_segments);
        const auto [cp, sp] = turn(j, minor_segments);
        const Vec3 radial = u * ct + w * st;
        const Vec3 n = radial * cp + a * sp;
        return std::pair{center + radial * major_radius + n * minor_radius, n};
    });
    return m;
}

Mesh make_arch(Vec3 c, float inner_radius, float half_width, float height, float depth,
               int segments) {
    // Angles of the opening's edge, placed so that rays through the outer corners are among
    // them; each inner point then pairs with the point of the rectangle on the same ray.
    segments = std::max(segments, 3);
    const float corner = std::atan2(height, half_width);
    const int side = std::clamp(int(std::lround(segments * corner / kPi)), 1, (segments - 1) / 2);
    const int mid = segments - 2 * side;
    std::vector<float> angles;
    for (int i = 0; i < side; ++i) angles.push_back(corner * float(i) / float(side));
    for (int i = 0; i < mid; ++i)
        angles.push_back(corner + (kPi - 2 * corner) * float(i) / float(mid));
    for (int i = 0; i <= side; ++i)
        angles.push_back(kPi - corner + corner * float(i) / float(side));
    const float zf = c.z + depth * 0.5f, zb = c.z - depth * 0.5f;
    std::vector<Vec3> inner, outer; // in the x-y plane, relative to c
    for (float t : angles) {
        const float ct = std::fabs(t - kPi * 0.5f) < 1e-6f ? 0.0f : std::cos(t);
        const float st = std::sin(t);
        inner.push_back(Vec3(ct, st, 0) * inner_radius);
        const float reach = std::min(std::fabs(ct) > 1e-6f ? half_width / std::fabs(ct) : 1e30f,
                                     st > 1e-6f ? height / st : 1e30f);
        outer.push_back(Vec3(ct, st, 0) * reach);
    }
    outer.front() = Vec3(half_width, 0, 0), outer.back() = Vec3(-half_width, 0, 0);
    inner.front() = Vec3(inner_radius, 0, 0), inner.back() = Vec3(-inner_radius, 0, 0);
    const uint32_t n = uint32_t(angles.size());

    Mesh m;
    // The front and back faces: quads between the opening and the rectangle.
    for (int face = 0; face < 2; ++face) {
        const float z = face == 0 ? zf : zb;
        const Vec3 normal(0, 0, face == 0 ? 1.0f : -1.0f);
        const uint32_t b = uint32_t(m.positions.size());
        for (uint32_t i = 0; i < n; ++i) {
            m.positions.push_back(Vec3(c.x, c.y, z) + inner[i]);
            m.positions.push_back(Vec3(c.x, c.y, z) + outer[i]);
            m.normals.insert(m.normals.end(), {normal, normal});
        }
        for (uint32_t i = 0; i + 1 < n; ++i) {
            const uint32_t p0 = b + 2 * i, o0 = p0 + 1, p1 = p0 + 2, o1 = p0 + 3;
            if (face == 0) {
                add_triangle(m, p0, o0, o1);
                add_triangle(m, p0, o1, p1);
            } else {
                add_triangle(m, p0, o1, o0);
                add_triangle(m, p0, p1, o1);
            }
        }
    }
    // The intrados, facing the opening's axis.
    const uint32_t b = uint32_t(m.positions.size());
    for (uint32_t i = 0; i < n; ++i) {
        const Vec3 toward_axis = -normalize(inner[i]);
        m.positions.push_back(Vec3(c.x, c.y, zf) + inner[i]);
        m.positions.push_back(Vec3(c.x, c.y, zb) + inner[i]);
        m.normals.insert(m.normals.end(), {toward_axis, toward_axis});
    }
    for (uint32_t i = 0; i + 1 < n; ++i) {
        const uint32_t f0 = b + 2 * i, b0 = f0 + 1, f1 = f0 + 2, b1 = f0 + 3;
        add_triangle(m, b0, f0, f1);
        add_triangle(m, b0, f1, b1);
    }
    // The outer sides, the top and the two feet.
    const Vec3 back(c.x, c.y, zb), dz(0, 0, depth), up(0, height, 0);
    append_quad(m, back + Vec3(half_width, 0, 0), up, dz, 1, 1);
    append_quad(m, back + Vec3(-half_width, 0, 0), dz, up, 1, 1);
    append_quad(m, back + Vec3(-half_width, height, 0), dz, Vec3(2 * half_width, 0, 0), 1, 1);
    const Vec3 foot(half_width - inner_radius, 0, 0);
    append_quad(m, back + Vec3(inner_radius, 0, 0), foot, dz, 1, 1);
    append_quad(m, back + Vec3(-half_width, 0, 0), foot, dz, 1, 1);
    return m;
}

void append_mesh(Mesh& dst, const Mesh& src, const Affine& t) {
    const bool keep_normals =
        (dst.positions.empty() || !dst.normals.empty()) && !src.normals.empty();
    if (!keep_normals) dst.normals.clear();
    const uint32_t base = uint32_t(dst.positions.size());
    for (const Vec3& p : src.positions) dst.positions.push_back(t.point(p));
    if (keep_normals)
        for (const Vec3& n : src.normals) dst.normals.push_back(t.normal(n));
    const bool mirrored = t.determinant() < 0;
    for (size_t i = 0; i + 2 < src.indices.size(); i += 3) {
        const uint32_t a = src.indices[i], b = src.indices[i + 1], c = src.indices[i + 2];
        if (mirrored)
            dst.indices.insert(dst.indices.end(), {base + a, base + c, base + b});
        else
            dst.indices.insert(dst.indices.end(), {base + a, base + b, base + c});
    }
}

} // namespace sheaf
