// trace() through the probe's BVH finds what a walk over every primitive in order finds: the
// nearest surface, and of surfaces at the same distance (a ray down a shared edge or through a
// shared vertex of a folded mesh) the lowest primitive's, so its normal too.
#include "io/pov/probe.h"

#include "core/geometry/ray_triangle.h"
#include "core/scene/analytic.h"
#include "io/pov/builder.h"
#include "tests/support/pov_test_util.h"

#include <gtest/gtest.h>

#include <cfloat>

namespace sheaf::io::pov {
namespace {

using test::TempDir;

// The walk over every primitive in order (what trace() did before its BVH).
bool brute_trace(const ObjectProbe& q, Vec3 from, Vec3 dir, Vec3& hit, Vec3& normal) {
    const Affine flip = pov_to_sheaf();
    const SceneView view(q.prepared);
    Ray r = probe_ray(from, dir);
    float best = FLT_MAX;
    Vec3 n(0.0f);
    for (size_t i = 0; i < q.prepared.tris.size(); ++i) {
        const TriangleVerts& tv = q.prepared.tris[i];
        TriangleHit h;
        if (intersect_triangle(r, tv.a, tv.b, tv.c, h) && h.t < best) {
            best = h.t, r.tmax = h.t, n = cross(tv.b - tv.a, tv.c - tv.a);
            if (dot(n, r.dir) > 0) n = -n;
        }
    }
    for (uint32_t a = 0; a < uint32_t(q.prepared.analytic_root.size()); ++a) {
        AnalyticHit h;
        if (analytic_first_hit(view, a, r, h) && h.t < best) best = h.t, r.tmax = h.t, n = h.normal;
    }
    if (!(best < FLT_MAX)) return false;
    hit = flip.point(ray_at(r, best));
    normal = length(n) > 0 ? normalize(flip.vector(n)) : Vec3(0.0f);
    return true;
}

TEST(PovProbe, TraceThroughTheBvhFindsWhatEveryPrimitiveInOrderFinds) {
    // A folded grid of 2 x 40 x 40 triangles (a ridge every other column, so neighbours
    // differ in normal), a sphere above it and a plane below.
    TempDir d;
    Parser p(PovOptions{});
    p.parse_scene(d.write("scene.pov", R"(
#declare G = union {
  mesh {
    #declare I = 0;
    #while (I < 40)
      #declare J = 0;
      #while (J < 40)
        #declare H0 = mod(I, 2) * 0.5; #declare H1 = mod(I + 1, 2) * 0.5;
        triangle { <I, H0, J>, <I + 1, H1, J>, <I + 1, H1, J + 1> }
        triangle { <I, H0, J>, <I + 1, H1, J + 1>, <I, H0, J + 1> }
        #declare J = J + 1;
      #end
      #declare I = I + 1;
    #end
  }
  sphere { <20, 3, 20>, 1 }
  plane { y, -1 }
}
)"));
    const Value* g = p.lookup("G");
    ASSERT_TRUE(g && g->type == VType::Object);
    Token at;
    at.text = "trace";
    const std::shared_ptr<const ObjectProbe> q = make_probe(p, g->as<PovObject>(), at);
    ASSERT_GT(q->bvh.nodes.size(), 10u);
    int hits = 0, ties = 0;
    for (int i = 0; i <= 80; ++i)
        for (int j = 0; j <= 12; ++j) {
            // Straight down on the grid's vertices and edges (ties), and slanted.
            const Vec3 from(float(i) * 0.5f, 6.0f, float(j) * 3.25f);
            for (const Vec3 dir : {Vec3(0, -1, 0), Vec3(0.3f, -1, 0.1f), Vec3(0, 0, 1)}) {
                Vec3 a, an, b, bn;
                const bool ha = probe_trace(*q, from, dir, a, an);
                const bool hb = brute_trace(*q, from, dir, b, bn);
                ASSERT_EQ(ha, hb) << i << " " << j;
                if (!ha) continue;
                ++hits;
                ties += i % 2 == 0 && dir.x == 0 && dir.z == 0 ? 1 : 0;
                EXPECT_EQ(a.x, b.x) << i << " " << j;
                EXPECT_EQ(a.y, b.y) << i << " " << j;
                EXPECT_EQ(a.z, b.z) << i << " " << j;
                EXPECT_EQ(an.x, bn.x) << i << " " << j;
                EXPECT_EQ(an.y, bn.y) << i << " " << j;
                EXPECT_EQ(an.z, bn.z) << i << " " << j;
            }
        }
    EXPECT_GT(hits, 2000);
    EXPECT_GT(ties, 400);
}

} // namespace
} // namespace sheaf::io::pov
