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
  +SR0.5 +ER1.0    a part of the image: start/end row (+SR +ER) and column (+SC +EC), each
                   a number from 1 or a fraction from 0.0 to 1.0 (--start-row ...); the
                   image written holds that part only
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
  render scene.pov +KFI1 +KFF24 +SF2 --frame-step 4
                                                 frames 2, 6, 10, ... (one machine of four)
  render scene.pov --tile 3/16 --set output.exr=float -o t3.exr
                                                 tile 3 of a 4x4 grid, as an OpenEXR part
  render --merge t*.exr -o frame.png             the tiles put together: the whole frame
  render scene.pov +SR0.5 +ER1.0 -o lower.png    the lower half of the image (POV-Ray's
                                                 +SR +ER +SC +EC: rows/columns or fractions)
  render scene.pov -W 3840 -H 2160 --farm slurm --farm-tiles 16 --farm-dir /shared/job1 \
      -o /shared/frame.png                       16 tiles as a Slurm job array, merged
  render scene.pov +KFI1 +KFF240 --farm slurm --farm-dir /shared/anim --farm-throttle 32
  render --farm-status --farm-dir /shared/job1 --farm-wait
                                                 tasks done, running, failed; time left
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
                   "objects, data_mib, loop_iterations, macro_calls, function_terms; "
                   "repeatable (render --check prints "
                   "what a scene uses of each)")
        ->allow_extra_args(false)
        ->type_name("NAME=N");
    std::string start_row, end_row, start_column, end_column, tile;
    CLI::Option* sr = app.add_option("--start-row", start_row,
                                     "render only a part of the image, from this row: a row from "
                                     "1, or a fraction of the height from 0.0 to 1.0 (+SR)")
                          ->type_name("ROW");
    CLI::Option* er = app.add_option("--end-row", end_row,
                                     "up to this row, included: a row, or a fraction 0.0 to 1.0 "
                                     "(+ER)")
                          ->type_name("ROW");
    CLI::Option* sc = app.add_option("--start-column", start_column,
                                     "from this column: a column from 1, or a fraction (+SC)")
                          ->type_name("COLUMN");
    CLI::Option* ec = app.add_option("--end-column", end_column,
                                     "up to this column, included: a column, or a fraction (+EC)")
                          ->type_name("COLUMN");
    CLI::Option* tile_opt =
        app.add_option("--tile", tile,
                       "render tile I of N (from 1; N tiles in a grid as square as N allows, "
                       "or I/CxR): the image holds that part only; render --merge puts the "
                       "tiles back together, equal to the whole frame")
            ->type_name("I/N");
    CLI::Option* step =
        app.add_option("--frame-step", o.frame_step,
                       "render every Nth frame of the animation from the first (interleaving "
                       "machines: +SF1, +SF2 ... with --frame-step N)")
            ->check(CLI::Range(1, 1000000))
            ->type_name("N");
    CLI::Option* merge =
        app.add_option("--merge", o.merge,
                       "put the parts of a frame (OpenEXR files written with --tile or "
                       "+SR/+ER/+SC/+EC and output.exr=float) together into -o FILE")
            ->allow_extra_args(true)
            ->type_name("PART.exr...");
    CLI::Option* farm =
        app.add_option("--farm", o.farm,
                       "run the render, animation (a task per --farm-chunk frames), tiled frame "
                       "(--farm-tiles) or --sweep (a task per point) on a cluster: slurm (a job "
                       "array and a merge job after it), or none (the plan, and its commands "
                       "printed for another scheduler); see docs/farm.md")
            ->type_name("SCHEDULER");
    CLI::Option* farm_dir = app.add_option(
        "--farm-dir", o.farm_dir,
        "the job's shared folder: its plan, the tasks' records and parts (--farm), or the job "
        "--farm-task/--farm-merge/--farm-status work on");
    farm_dir->type_name("DIR");
    CLI::Option* farm_tiles =
        app.add_option("--farm-tiles", o.farm_tiles,
                       "with --farm: cut the frame into N tiles (or CxR), a task each; the merge "
                       "job puts them together, equal to the whole frame")
            ->type_name("N");
    CLI::Option* farm_chunk =
        app.add_option("--farm-chunk", o.farm_chunk, "with --farm: frames per task (1)")
            ->check(CLI::Range(1, 1000000))
            ->type_name("N");
    CLI::Option* farm_throttle =
        app.add_option("--farm-throttle", o.farm_throttle,
                       "with --farm: at most N tasks running at once (Slurm's --array=...%N)")
            ->check(CLI::Range(1, 1000000))
            ->type_name("N");
    CLI::Option* farm_sbatch =
        app.add_option("--farm-sbatch", o.farm_sbatch,
                       "with --farm slurm: more sbatch options for every job, e.g. "
                       "\"--partition=gpu --gres=gpu:1 --time=2:00:00\"")
            ->type_name("OPTIONS");
    CLI::Option* farm_print =
        app.add_flag("--farm-print", o.farm_print,
                     "with --farm: write the plan, print the batch scripts and the commands that "
                     "submit them; submit nothing");
    int farm_task_index = 0;
    CLI::Option* farm_task = app.add_option("--farm-task", farm_task_index,
                                            "run task I (from 1) of the job in --farm-dir; "
                                            "skipped when its outputs are complete")
                                 ->type_name("I");
    CLI::Option* farm_merge_opt =
        app.add_flag("--farm-merge", o.farm_merge,
                     "put the job's tiles (or sweep results) together once every task is done");
    CLI::Option* farm_status_opt = app.add_flag(
        "--farm-status", o.farm_status,
        "the job's tasks: done, running, failed, waiting, and the time left");
    CLI::Option* farm_wait = app.add_flag(
        "--farm-wait", o.farm_wait,
        "with --farm or --farm-status: show the progress until the job ends (exit 3 on a failed "
        "task)");
    for (CLI::Option* opt : {input_opt, output, default_out, w, h, t, preset, stats_json, report,
                             fi, ff, ic, fc, sf, ef, clock_opt, sr, er, sc, ec, tile_opt, step,
                             farm, farm_dir, farm_tiles, farm_chunk, farm_throttle, farm_sbatch,
                             farm_task})
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
    farm->excludes(compare)->excludes(merge)->excludes(check)->excludes(stats)->excludes(stats_json);
    input_opt->excludes(scene);
    check->excludes(compare)->excludes(sweep)->excludes(stats)->excludes(stats_json)->excludes(output);
    merge->excludes(compare)->excludes(sweep)->excludes(check)->excludes(scene)->excludes(input_opt);
    for (CLI::Option* part : {sr, er, sc, ec, tile_opt})
        part->excludes(compare)->excludes(sweep)->excludes(merge);
    try {
        std::reverse(args.begin(), args.end()); // CLI11 takes the arguments reversed
        app.parse(args);
        if (report->count() && !compare->count() && !sweep->count() && !farm->count())
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
    if (sr->count()) o.region.start_row = start_row;
    if (er->count()) o.region.end_row = end_row;
    if (sc->count()) o.region.start_column = start_column;
    if (ec->count()) o.region.end_column = end_column;
    if (tile_opt->count()) o.region.tile = tile;
    try {
        check_region_request(o.region);
    } catch (const RegionError& e) {
        return error(kUsage, std::string(e.what()) + " (see render --help)");
    }
    if (farm_task->count()) o.farm_task = farm_task_index;
    const int farm_steps = int(farm->count() > 0) + int(farm_task->count() > 0) +
                           int(farm_merge_opt->count() > 0) + int(farm_status_opt->count() > 0);
    if (farm_steps > 1)
        return error(kUsage, "--farm, --farm-task, --farm-merge and --farm-status are separate "
                             "steps: give one (see render --help)");
    if (farm_steps == 1 && !farm_dir->count())
        return error(kUsage, "the farm's steps need --farm-dir DIR, the job's shared folder "
                             "(see render --help)");
    if (farm_steps == 0)
        for (CLI::Option* only : {farm_dir, farm_tiles, farm_chunk, farm_throttle, farm_sbatch,
                                  farm_print, farm_wait})
            if (only->count())
                return error(kUsage, only->get_name() + " goes with --farm (see render --help)");
    if (farm->count() && o.sweep.size() > 0 && !report->count())
        return error(kUsage, "--farm with --sweep needs --report DIR, where the merge job writes "
                             "the results (see render --help)");
    if (report->count() && farm->count() && o.sweep.empty())
        return error(kUsage, "--report needs --compare or --sweep (see render --help)");
    if (merge->count() && !output->count())
        return error(kUsage, "--merge needs -o FILE, the whole frame to write (see render --help)");
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
