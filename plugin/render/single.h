// The plain render: one scene, one renderer, one image file, optional statistics.
#pragma once

#include "options.h"

namespace render {

/// Renders o.scene with o.preset and the common settings to o.output; returns the exit code.
int run_single(const Options& o);

/// --check: loads and builds the scene without rendering, prints its warnings and a verdict;
/// 0 when the scene is usable.
int run_check(const Options& o);

/// Sets the renderer's region.* to the part `region` names of the frame `scene` renders at
/// (its effective width and height); nothing when it names none. Returns an exit code.
int apply_region(SheafRenderer renderer, SheafScene scene, const RegionRequest& region);
/// output.passes=combined when it is at its default and `output` is not OpenEXR (the only
/// format that holds the other passes): the frame keeps only what is written.
int keep_written_passes(SheafRenderer renderer, SheafScene scene, const std::string& output);

/// FILE.EXT with the frame number before the extension, zero-padded to the digits of `last`,
/// as POV-Ray names an animation's images (render.png, frame 3 of 1..12: render03.png).
std::string numbered(const std::string& file, int frame, int last);

/// The last frame number as the scene sees it (one more when cyclic), for the names' digits.
int name_digits_frame(const Options& o);

/// Where `file` is written before it is renamed to its name: DIR/.NAME.partial-PID.EXT (the
/// extension kept: it picks the format).
std::string partial_name(const std::string& file);

/// Saves the frame to `output` through a temporary file renamed when whole; prints the error
/// and returns its exit code on failure.
int save_image(SheafFrame frame, const std::string& output);

/// --stats (the tables on stdout when `table`) and --stats-json FILE (when not empty) of the
/// frame; prints the error and returns its exit code on failure.
int write_stats(SheafFrame frame, bool table, const std::string& stats_json);

/// Prints every setting, its default, what it allows and its help.
void list_settings();

} // namespace render
