// The render tool's options through CLI11, after POV-Ray switch translation.
#include "options.h"

#include "pov_switches.h"

#include <CLI/CLI.hpp>

#include <algorithm>

namespace render {

namespace {

const char* const kFooter =
    R"(Settings apply in this order: the preset, then -W/-H/--threads, then each --set
(and +A/-A) in the order given.
Exit codes: 0 ok, 1 usage or settings, 2 scene, 3 render, image write, or --compare images
that differ.

POV-Ray switches (translated before parsing; no space between switch and value):
  +W640 +H480      image size (-W 640 -H 480)
  +Ofile.png       output file (-o file.png)
  +Ifile           input scene (--input file)
  +A, +A0.3        anti-aliasing on: aa.samples=3, 3x3 samples per pixel, POV-Ray's default
                   antialias depth; the threshold is accepted and ignored (sampling is not
                   adaptive)
  -A               anti-aliasing off: aa.samples=1
  +L<dir>          a folder searched for #include (--include-path dir)
  -D, +D           display: accepted, does nothing (render never opens a window)
  +KFI1 +KFF24     an animation: frames 1 to 24, each written as OUTPUT with its number
                   (render01.png ... render24.png); the scene's clock runs from +KI<v> (0)
                   to +KF<v> (1); +KC cyclic; +SF<n> +EF<n> render a subset of the frames
  +K0.5            the clock of a single image
  scene.ini        POV-Ray's .ini file in place of the scene (also FILE.ini[Section]); its
                   Key=Value options (Width=, Input_File_Name=, Initial_Frame=, Declare= ...)
                   are also taken on the command line

Examples:
  render                                         the default built-in scene to render.png
  render scenes/glass.pov -W 800 -H 600 -o glass.png
                                                 a POV-Ray scene (warnings on stderr)
  render --check scene.pov --strict              parse and build only; unsupported is an error
  render builtin:cornell -W 640 -H 480 -o cornell.exr
  render builtin:office +W640 +H480 +A +Ooffice.png
  render builtin:office --preset rah --stats     the Roger et al. hierarchy, with statistics
  render --set accel=brute --set trace.depth=2 --stats-json stats.json
  render --compare crsh,rah,brute builtin:cornell --report cmp
                                                 the papers' tables side by side, images
                                                 checked identical, cmp/report.html
  render --sweep hierarchy.depth=1..4 hierarchy.arity=2,4,8,16 builtin:office --report sw
                                                 the grid's tests and times, the best named
  render scene.pov +KFI1 +KFF24 +Oframe.png      frame01.png ... frame24.png
  render p_skies.ini                             the .ini's scene, size and frames
  render --list-settings                         every key, its default and what it allows
See docs/cli.md.)";

} // namespace

std::optional<int> parse_options(int argc, char** argv, Options& o) {
    std::vector<std::string> raw(argv + 1, argv + argc);
    for (const std::string& a : raw) o.command_line += (o.command_line.empty() ? "" : " ") + a;
    o.command_line = "render " + o.command_line;
    std::vector<std::string> args;
    try {
        args = translate_args(raw);
    } catch (const SwitchError& e) {
        return error(kUsage, std::string(e.what()) + " (see render --help)");
    }

    CLI::App app{"render: renders a scene with the Sheaf engine and writes an image; compares "
                 "presets and sweeps settings with the papers' tables and an HTML report."};
    app.name("render");
    app.footer(kFooter);
    std::string input;
    int width = 0, height = 0, threads = 0;
    CLI::Option* scene = app.add_option(
        "scene", o.scene,
        "builtin:NAME, a scene file (.pov .xml .obj .ply .gltf .glb) or a POV-Ray .ini "
        "(default: the built-in " +
            std::string(sheafGetDefaultSceneName()) + " scene)");
    CLI::Option* input_opt =
        app.add_option("-i,--input", input, "the scene, as the positional argument (+IFILE)")
            ->type_name("FILE");
    CLI::Option* output = app.add_option("-o,--output", o.output,
                                         "image file; the extension picks the format: .png .jpg "
                                         ".tif .exr .hdr (+OFILE)")
                              ->capture_default_str();
    std::string default_output;
    CLI::Option* default_out =
        app.add_option("--default-output", default_output,
                       "the image file when -o is not given (what a POV-Ray .ini names)")
            ->type_name("FILE");
    CLI::Option* w = app.add_option("-W,--width", width, "image width in pixels (+W)");
    CLI::Option* h = app.add_option("-H,--height", height, "image height in pixels (+H)");
    CLI::Option* t =
        app.add_option("--threads", threads, "worker threads (setting threads; 0: every core)");
    CLI::Option* preset =
        app.add_option("--preset", o.preset, "a preset name (brute, rah, crsh, ...) or .xml file");
    app.add_option("--set", o.settings.sets,
                   "a setting, key=value; repeatable (see --list-settings)")
        ->allow_extra_args(false)
        ->type_name("KEY=VALUE");
    CLI::Option* stats = app.add_flag("--stats", o.stats, "print the frame statistics as tables");
    CLI::Option* stats_json =
        app.add_option("--stats-json", o.stats_json, "write the frame statistics as JSON to FILE")
            ->type_name("FILE");
    CLI::Option* compare =
        app.add_option("--compare", o.compare,
                       "render the scene once per preset (comma separated: crsh,rah,brute), "
                       "check the images agree (exit 3 if not) and print the tables side by side")
            ->delimiter(',')
            ->allow_extra_args(false)
            ->type_name("PRESETS");
    CLI::Option* sweep =
        app.add_option("--sweep", o.sweep,
                       "render over a grid of settings: KEY=A..B (integers) or KEY=V1,V2,...; "
                       "several axes may follow one --sweep; --preset gives the base")
            ->allow_extra_args(false)
            ->type_name("KEY=VALUES");
    CLI::Option* report =
        app.add_option("--report", o.report,
                       "with --compare or --sweep: write DIR/report.html, results.json, "
                       "results.csv and the images")
            ->type_name("DIR");
    app.add_flag("-q,--quiet", o.quiet, "no progress bar and no 'wrote' lines");
    app.add_option("--include-path", o.include_paths,
                   "a folder searched for #include after the scene's own; repeatable (+L)")
        ->allow_extra_args(false)
        ->type_name("DIR");
    app.add_flag("--strict", o.strict,
                 "an unsupported feature of the scene file is an error (exit 2), not a warning");
    CLI::Option* check = app.add_flag(
        "--check", o.check,
        "load and build the scene without rendering, print its warnings; exit 0 when usable");
    int initial_frame = 0, final_frame = 0, subset_start = 0, subset_end = 0;
    double initial_clock = 0, final_clock = 0, clock = 0;
    CLI::Option* fi = app.add_option("--initial-frame", initial_frame,
                                     "POV-Ray animation: the first frame's number (+KFI; 1)");
    CLI::Option* ff = app.add_option("--final-frame", final_frame,
                                     "the last frame's number (+KFF; 1): frames from the first "
                                     "to the last, each written as OUTPUT with its number");
    CLI::Option* ic = app.add_option("--initial-clock", initial_clock,
                                     "the scene's clock at the first frame (+KI; 0)");
    CLI::Option* fc = app.add_option("--final-clock", final_clock,
                                     "the scene's clock at the last frame (+KF; 1)");
    bool cyclic_flag = false;
    CLI::Option* cyclic = app.add_flag("--cyclic-animation,!--no-cyclic-animation", cyclic_flag,
                                       "the last frame stops one step short of the final clock "
                                       "(+KC, -KC)");
    CLI::Option* sf = app.add_option("--subset-start-frame", subset_start,
                                     "render the frames from this one (+SF)");
    CLI::Option* ef =
        app.add_option("--subset-end-frame", subset_end, "render the frames up to this one (+EF)");
    CLI::Option* clock_opt =
        app.add_option("--clock", clock, "the clock of a single image (+K; 0)");
    app.add_option("--declare", o.declares,
                   "NAME=NUMBER: a float declared before the scene's first line "
                   "(POV-Ray's Declare=); repeatable")
        ->allow_extra_args(false)
        ->type_name("NAME=NUMBER");
    app.add_option("--limit", o.limits,
                   "NAME=N: raise (or lower) one of the scene reader's limits: parse_steps, "
                   "objects, data_mib, loop_iterations; repeatable (render --check prints "
                   "what a scene uses of each)")
        ->allow_extra_args(false)
        ->type_name("NAME=N");
    for (CLI::Option* opt : {input_opt, output, default_out, w, h, t, preset, stats_json, report,
                             fi, ff, ic, fc, sf, ef, clock_opt})
        opt->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    bool no_display = false;
    app.add_flag("--no-display", no_display, "accepted for POV-Ray's -D; does nothing");
    app.add_flag("--list-settings", o.list_settings, "list every setting and exit");
    app.add_flag("--version", o.version, "print the version and exit");

    compare->excludes(sweep)
        ->excludes(preset)
        ->excludes(stats)
        ->excludes(stats_json)
        ->excludes(output);
    sweep->excludes(stats)->excludes(stats_json)->excludes(output);
    input_opt->excludes(scene);
    check->excludes(compare)->excludes(sweep)->excludes(stats)->excludes(stats_json)->excludes(output);
    try {
        std::reverse(args.begin(), args.end()); // CLI11 takes the arguments reversed
        app.parse(args);
        if (report->count() && !compare->count() && !sweep->count())
            throw CLI::ValidationError("--report", "needs --compare or --sweep");
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return error(kUsage, std::string(e.what()) + " (see render --help)");
    }
    if (input_opt->count()) o.scene = input;
    if (fi->count()) o.initial_frame = initial_frame;
    if (ff->count()) o.final_frame = final_frame;
    if (ic->count()) o.initial_clock = initial_clock;
    if (fc->count()) o.final_clock = final_clock;
    if (sf->count()) o.subset_start = subset_start;
    if (ef->count()) o.subset_end = subset_end;
    if (clock_opt->count()) o.clock = clock;
    if (cyclic->count()) o.cyclic = cyclic_flag;
    if (o.final_frame.value_or(1) < o.initial_frame.value_or(1))
        return error(kUsage, "--final-frame " + std::to_string(o.final_frame.value_or(1)) +
                                 " is below --initial-frame " +
                                 std::to_string(o.initial_frame.value_or(1)) +
                                 " (see render --help)");
    if (o.sequence() && o.first_frame() > o.last_frame())
        return error(kUsage, "--subset-start-frame and --subset-end-frame leave no frame of " +
                                 std::to_string(o.initial_frame.value_or(1)) + ".." +
                                 std::to_string(o.final_frame.value_or(1)) +
                                 " to render (see render --help)");
    if (o.sequence() && (compare->count() || sweep->count()))
        return error(kUsage, std::string(compare->count() ? "--compare" : "--sweep") +
                                 " renders one frame; give --clock (+K) instead of a sequence of "
                                 "frames (see render --help)");
    o.has_output = output->count() > 0;
    if (!o.has_output && default_out->count()) {
        o.output = default_output;
        o.has_output = true;
    }
    if (w->count()) o.settings.width = width;
    if (h->count()) o.settings.height = height;
    if (t->count()) o.settings.threads = threads;
    return std::nullopt;
}

} // namespace render
