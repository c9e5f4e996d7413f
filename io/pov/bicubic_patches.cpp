// bicubic_patch: a bicubic Bezier patch of 16 control points, tessellated into a smooth mesh.
// POV-Ray intersects flat pieces of the patch (u_steps and v_steps subdivisions, or as many as
// flatness asks) and shades with the patch's own normal there; Sheaf does the same with a grid
// of at least 16 x 16 quads (2^u_steps x 2^v_steps when that is finer, up to 64 x 64), so
// the silhouette is at least as smooth as POV-Ray's and the shading follows the exact normal.
#include "io/pov/parser.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace sheaf::io::pov {

namespace {

// The cubic Bernstein basis at t and its derivative.
void bernstein(double t, double b[4], double d[4]) {
    const double s = 1 - t;
    b[0] = s * s * s, b[1] = 3 * t * s * s, b[2] = 3 * t * t * s, b[3] = t * t * t;
    d[0] = -3 * s * s, d[1] = 3 * s * s - 6 * t * s, d[2] = 6 * t * s - 3 * t * t, d[3] = 3 * t * t;
}

int segments(double steps) {
    const int n = 1 << std::clamp(int(steps), 0, 6);
    return std::max(n, 16);
}

} // namespace

bool Parser::parse_bicubic_patch(const Token& kw, PovObject& o) {
    expect_sym("{");
    double u_steps = 0, v_steps = 0;
    bool typed = false;
    // Its settings come before the points, in any order; "v_steps 3 <0, 0, 0>" is a setting
    // and the first point, not a comparison.
    ++no_lt_;
    for (;;) {
        const Token& t = peek();
        if (accept_kw("type")) {
            const double type = parse_float();
            if (type != 0 && type != 1) error_at(t, "a bicubic_patch's type must be 0 or 1");
            typed = true;
        } else if (accept_kw("u_steps")) {
            u_steps = parse_float();
        } else if (accept_kw("v_steps")) {
            v_steps = parse_float();
        } else if (accept_kw("flatness") || accept_kw("accuracy")) {
            parse_float();
        } else if (accept_kw("uv_vectors")) {
            // The corners' uv coordinates: only a uv_mapping texture uses them, and that is
            // warned where it is read.
            for (int k = 0; k < 4; ++k) {
                if (k > 0) accept_sym(",");
                parse_expr();
            }
        } else {
            break;
        }
    }
    --no_lt_;
    if (!typed) error_expected(peek(), "the bicubic_patch's type (type 0 or type 1)");
    std::array<Vec3, 16> p;
    for (int k = 0; k < 16; ++k) {
        accept_sym(","); // also after the settings: "v_steps 4, <0, 0, 0>, ..."
        const Token& at = peek();
        if (is_sym_tok(at, "}"))
            error_expected(at,
                           "control point " + std::to_string(k + 1) + " of the bicubic_patch's 16");
        p[size_t(k)] = parse_vector();
        if (!std::isfinite(p[size_t(k)].x) || !std::isfinite(p[size_t(k)].y) ||
            !std::isfinite(p[size_t(k)].z))
            error_at(at, "a bicubic_patch's control point must be finite");
    }
    bool texture_here = false;
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (accept_kw("uv_vectors")) { // the texture corners: Sheaf's meshes take no POV uv
            for (int k = 0; k < 4; ++k) {
                if (k > 0) accept_sym(",");
                parse_vector();
            }
        } else if (!parse_modifier(o, texture_here)) {
            error_expected(t, "uv_vectors, a modifier or '}'");
        }
    }

    // Rows i (the first index of the points, in fours) along v, columns j along u.
    const int nu = segments(u_steps), nv = segments(v_steps);
    auto mesh = std::make_shared<Mesh>();
    const size_t verts = size_t(nu + 1) * size_t(nv + 1);
    charge(verts * sizeof(Vec3) * 2 + size_t(nu) * size_t(nv) * 6 * 4, kw);
    mesh->positions.reserve(verts);
    mesh->normals.reserve(verts);
    for (int a = 0; a <= nv; ++a) {
        double bv[4], dv[4];
        bernstein(double(a) / nv, bv, dv);
        for (int c = 0; c <= nu; ++c) {
            double bu[4], du[4];
            bernstein(double(c) / nu, bu, du);
            double s[3] = {0, 0, 0}, su[3] = {0, 0, 0}, sv[3] = {0, 0, 0};
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) {
                    const Vec3& q = p[size_t(i * 4 + j)];
                    for (int e = 0; e < 3; ++e) {
                        s[e] += bv[i] * bu[j] * q[e];
                        su[e] += bv[i] * du[j] * q[e];
                        sv[e] += dv[i] * bu[j] * q[e];
                    }
                }
            mesh->positions.push_back(Vec3(float(s[0]), float(s[1]), float(s[2])));
            // The exact normal; zero where the patch is pinched (a corner whose edge points
            // coincide), mended from the faces below.
            mesh->normals.push_back(Vec3(float(su[1] * sv[2] - su[2] * sv[1]),
                                         float(su[2] * sv[0] - su[0] * sv[2]),
                                         float(su[0] * sv[1] - su[1] * sv[0])));
        }
    }
    auto at = [&](int c, int a) { return uint32_t(size_t(a) * size_t(nu + 1) + size_t(c)); };
    std::vector<Vec3> face_sum(verts, Vec3(0, 0, 0));
    for (int a = 0; a < nv; ++a)
        for (int c = 0; c < nu; ++c) {
            const uint32_t q[4] = {at(c, a), at(c + 1, a), at(c + 1, a + 1), at(c, a + 1)};
            for (const auto& tri : {std::array<uint32_t, 3>{q[0], q[1], q[2]},
                                    std::array<uint32_t, 3>{q[0], q[2], q[3]}}) {
                const Vec3 fn = cross(mesh->positions[tri[1]] - mesh->positions[tri[0]],
                                      mesh->positions[tri[2]] - mesh->positions[tri[0]]);
                if (!(length_squared(fn) > 0)) continue; // a pinched corner's sliver
                for (uint32_t k : tri) {
                    mesh->indices.push_back(k);
                    face_sum[k] += fn;
                }
            }
        }
    if (mesh->indices.empty()) {
        unsupported(kw, "degenerate shape: a bicubic_patch whose points enclose no area (left "
                        "out)");
        return false;
    }
    for (size_t k = 0; k < verts; ++k) {
        Vec3& n = mesh->normals[k];
        // The exact normal, on the faces' side (the grid's winding decides nothing in POV-Ray:
        // the surface is seen from both sides).
        if (!(length_squared(n) > 1e-24f) || !std::isfinite(length_squared(n))) n = face_sum[k];
        if (dot(n, face_sum[k]) < 0) n = -n;
        // Scaled first: a patch thousands of units across overflows float's squares.
        const float big = std::max({std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)});
        n = big > 0 && std::isfinite(big) ? normalize(n / big) : Vec3(0, 1, 0);
    }
    o.kind = PovKind::Mesh;
    o.mesh = std::move(mesh);
    return true;
}

} // namespace sheaf::io::pov
