// render: renders a scene to an image file, compares presets or sweeps settings, through the
// C ABI (libsheaf.so) only. The modes live in single.cpp, compare.cpp and sweep.cpp.
#include "compare.h"
#include "farm.h"
#include "merge.h"
#include "options.h"
#include "single.h"
#include "sweep.h"

#include <iostream>

int main(int argc, char** argv) {
    using namespace render;
    Options o;
    if (std::optional<int> done = parse_options(argc, argv, o)) return *done;
    if (o.version) {
        std::cout << "render (Sheaf) " << sheafGetVersionString() << "\n";
        return kOk;
    }
    if (o.list_settings) {
        list_settings();
        return kOk;
    }
    if (o.check) return run_check(o);
    if (!o.merge.empty()) return run_merge(o);
    if (!o.farm.empty()) return run_farm_submit(o);
    if (o.farm_task) return run_farm_task(o);
    if (o.farm_merge) return run_farm_merge(o);
    if (o.farm_status) return run_farm_status(o);
    if (!o.compare.empty()) return run_compare(o);
    if (!o.sweep.empty()) return run_sweep(o);
    return run_single(o);
}
