// The sweep: the axes and every value are checked before anything renders, then one renderer
// per grid point over one committed scene.
#include "sweep.h"

#include "grid.h"
#include "progress.h"
#include "report_dir.h"
#include "sweep_report.h"
#include "tables.h"

#include <iostream>

namespace render {

namespace {

/// Checks every key and value of the axes against the library; prints the error and returns
/// its exit code on the first bad one.
int check_axes(const std::vector<Axis>& axes) {
    SheafRenderer raw = nullptr;
    if (sheafRendererNew(&raw) != SHEAF_OK) return error(kRender, last_error());
    Renderer scratch(raw);
    for (const Axis& a : axes) {
        if (!is_setting_key(a.key))
            return error(kUsage, "--sweep: unknown setting '" + a.key +
                                     "'; known settings: " + setting_keys());
        for (const std::string& v : a.values)
            if (sheafRendererSetString(raw, a.key.c_str(), v.c_str()) != SHEAF_OK)
                return error(kUsage, "--sweep " + a.key + "=" + v + ": " + last_error());
    }
    return kOk;
}

} // namespace

std::vector<Axis> sweep_axes(const Options& o) {
    std::vector<Axis> axes;
    for (const std::string& spec : o.sweep) axes.push_back(parse_axis(spec));
    return axes;
}

std::string point_name(const std::vector<std::pair<std::string, std::string>>& point) {
    std::string name;
    for (const auto& [key, value] : point) name += (name.empty() ? "" : " ") + key + "=" + value;
    return name;
}

int run_sweep(const Options& o) {
    std::vector<Axis> axes;
    std::vector<std::vector<std::pair<std::string, std::string>>> points;
    try {
        axes = sweep_axes(o);
        points = grid_points(axes);
    } catch (const GridError& e) {
        return error(kUsage, e.what());
    }
    if (int rc = check_axes(axes)) return rc;
    {
        // The base settings on their own, so a bad preset or --set fails before the scene loads.
        SheafRenderer raw = nullptr;
        if (sheafRendererNew(&raw) != SHEAF_OK) return error(kRender, last_error());
        Renderer base(raw);
        if (int rc = apply_settings(raw, o.preset, o.settings)) return rc;
    }
    SheafScene raw_scene = nullptr;
    if (sheafSceneNew(&raw_scene) != SHEAF_OK) return error(kRender, last_error());
    Scene scene(raw_scene);
    if (int rc = load_scene(scene.get(), scene_source(o))) return rc;

    std::vector<RunResult> results(points.size());
    Progress progress(Progress::wanted(o.quiet), int(points.size()));
    for (size_t i = 0; i < points.size(); ++i) {
        RunResult& r = results[i];
        r.grid = points[i];
        r.name = point_name(r.grid);
        SheafRenderer raw = nullptr;
        if (sheafRendererNew(&raw) != SHEAF_OK) return error(kRender, last_error());
        Renderer renderer(raw);
        if (int rc = apply_settings(raw, o.preset, o.settings)) return rc;
        for (const auto& [key, value] : r.grid)
            if (sheafRendererSetString(raw, key.c_str(), value.c_str()) != SHEAF_OK)
                return error(kUsage, "--sweep " + key + "=" + value + ": " + last_error());
        progress.start_run(raw, int(i), r.name);
        const int rc = render_into(raw, scene.get(), false, r);
        progress.finish_run(raw);
        if (rc) return rc;
    }

    return report_sweep(o, axes, results);
}

int report_sweep(const Options& o, const std::vector<Axis>& axes,
                 const std::vector<RunResult>& results) {
    if (!o.quiet) std::cerr << backend_summary(results) << "\n";
    const Best best = find_best(results);
    std::cout << sweep_table(results, best) << best_lines(results, best);
    if (o.report.empty()) return kOk;
    ResultsMeta meta{
        "sweep", scene_label(o.scene), o.command_line, sheafGetVersionString(), std::nullopt, best};
    if (int rc = make_report_dir(o.report, false)) return rc;
    return write_report_texts(o.report, sweep_html(meta, axes, results, best), meta, results,
                              o.quiet);
}

} // namespace render
