// The comparison: every preset's renderer is set up before anything renders (so a bad preset
// fails at once), the scene is loaded once, each image is checked against the first.
#include "compare.h"

#include "compare_report.h"
#include "images.h"
#include "progress.h"
#include "report_dir.h"
#include "tables.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace render {

namespace {

constexpr float kDifferenceGain = 16.0f;

/// The rendered image of result `index` inside the report directory.
std::string image_name(size_t index, const std::string& name) {
    return "images/" + file_stem(index, name) + ".png";
}

/// Writes the derived images, the page and the results files into o.report (the rendered
/// images are there already).
int write_compare_report(const Options& o, const ResultsMeta& meta,
                         const std::vector<RunResult>& results,
                         const std::vector<std::string>& differences) {
    CompareImages im;
    im.gain = kDifferenceGain;
    for (const RunResult& r : results)
        for (float t : r.tests) {
            im.max_tests = std::max(im.max_tests, double(t));
            if (t > 0 && (im.min_tests == 0 || t < im.min_tests)) im.min_tests = t;
        }
    for (size_t i = 0; i < results.size(); ++i) {
        const RunResult& r = results[i];
        const std::string stem = "images/" + file_stem(i, r.name);
        im.image.push_back(image_name(i, r.name));
        im.difference.push_back(i == 0 ? "" : stem + "-difference.png");
        im.heat.push_back(stem + "-tests.png");
        int rc = kOk;
        if (i > 0)
            rc = write_report_image(o.report, im.difference[i], r.width, r.height, 3,
                                    difference_image(results[0], r, kDifferenceGain), false);
        if (!rc)
            rc = write_report_image(o.report, im.heat[i], r.width, r.height, 3,
                                    heat_map(r.tests, im.min_tests, im.max_tests), false);
        if (rc) return rc;
    }
    return write_report_texts(o.report, compare_html(meta, results, differences, im), meta, results,
                              o.quiet);
}

} // namespace

int run_compare(const Options& o) {
    std::vector<Renderer> renderers;
    for (const std::string& preset : o.compare) {
        if (preset.empty()) return error(kUsage, "--compare: an empty preset name");
        SheafRenderer raw = nullptr;
        if (sheafRendererNew(&raw) != SHEAF_OK) return error(kRender, last_error());
        renderers.emplace_back(raw);
        if (int rc = apply_settings(raw, preset, o.settings)) return rc;
    }
    SheafScene raw_scene = nullptr;
    if (sheafSceneNew(&raw_scene) != SHEAF_OK) return error(kRender, last_error());
    Scene scene(raw_scene);
    if (int rc = load_scene(scene.get(), scene_source(o))) return rc;

    if (!o.report.empty())
        if (int rc = make_report_dir(o.report, true)) return rc;

    std::vector<RunResult> results(o.compare.size());
    Progress progress(Progress::wanted(o.quiet), int(results.size()));
    for (size_t i = 0; i < results.size(); ++i) {
        results[i].name = o.compare[i];
        const std::string image =
            o.report.empty()
                ? std::string()
                : (std::filesystem::path(o.report) / image_name(i, results[i].name)).string();
        progress.start_run(renderers[i].get(), int(i), results[i].name);
        const int rc = render_into(renderers[i].get(), scene.get(), true, results[i], image);
        progress.finish_run(renderers[i].get());
        if (rc) return rc;
    }

    if (!o.quiet) std::cerr << backend_summary(results) << "\n";
    std::vector<std::string> differences(results.size());
    bool identical = true;
    for (size_t i = 1; i < results.size(); ++i) {
        const ImageDiff d = compare_images(results[0], results[i]);
        if (d.size_differs || d.count > 0) {
            differences[i] = describe(d, results[0], results[i]);
            identical = false;
        }
    }

    std::cout << type_tables(results) << totals_table(results) << phase_table(results);
    if (identical)
        std::cout << "images: all " << results.size() << " identical to " << results[0].name
                  << "'s\n";
    const ResultsMeta meta{"compare", scene_label(o.scene), o.command_line, sheafGetVersionString(),
                           identical, std::nullopt};
    int rc = kOk;
    if (!o.report.empty()) rc = write_compare_report(o, meta, results, differences);
    for (const std::string& d : differences)
        if (!d.empty()) error(kRender, "images differ: " + d);
    return rc ? rc : identical ? kOk : kRender;
}

} // namespace render
