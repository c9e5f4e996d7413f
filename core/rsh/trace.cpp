#include "core/rsh/trace.h"

#include "core/shading/shadow_pass.h"

#include <string>

namespace sheaf {

Vec3 TraceResult::pass(size_t i) const {
    if (pass_log.empty()) return Vec3(1.0f);
    return pass_from_logs(&pass_log[3 * i]);
}

bool shadows_pass_surfaces(const PreparedScene& scene) {
    for (uint8_t f : scene.prim_flags)
        if (f & kPrimMayPass) return true;
    return false;
}

namespace {

void add_row(Stats& stats, const std::string& row, const TestCount& c) {
    stats.add(row + "tests", double(c.tests));
    stats.add(row + "hits", double(c.hits));
    stats.add(row + "misses", double(c.tests - c.hits));
}

} // namespace

void add_test_counts(Stats& stats, const std::string& p, bool cull_objects,
                     const TestCount& objects, const std::vector<TestCount>& levels,
                     const TestCount& final, const TestCount* nodes) {
    if (cull_objects) add_row(stats, p + "objects.", TestCount{});
    for (size_t k = levels.size(); k-- > 1;)
        add_row(stats, p + "level" + std::to_string(k) + ".", TestCount{});
    if (nodes) add_row(stats, p + "nodes.", TestCount{});
    add_row(stats, p + "final.", TestCount{});
    stats.add(p + "total", 0.0);
    add_late_counts(stats, p, cull_objects, objects, levels, final, nodes);
}

void add_late_counts(Stats& stats, const std::string& p, bool cull_objects,
                     const TestCount& objects, const std::vector<TestCount>& levels,
                     const TestCount& final, const TestCount* nodes) {
    if (cull_objects) add_row(stats, p + "objects.", objects);
    uint64_t total = final.tests;
    for (size_t k = levels.size(); k-- > 1;) {
        add_row(stats, p + "level" + std::to_string(k) + ".", levels[k]);
        total += levels[k].tests;
    }
    if (nodes) {
        add_row(stats, p + "nodes.", *nodes);
        total += nodes->tests;
    }
    add_row(stats, p + "final.", final);
    stats.add(p + "total", double(total));
}

} // namespace sheaf
