// The report directory: creating it, naming files inside it, and writing its images through the
// C ABI (sheafWriteImage) and its texts.
#pragma once

#include "results_files.h"
#include "run_result.h"

#include <string>
#include <vector>

namespace render {

/// Creates DIR (and DIR/images with `images`); prints the error and returns its exit code on
/// failure.
int make_report_dir(const std::string& dir, bool images);

/// "2-crsh-d2-a8": the index and the preset name (a path's file name without .xml) with any
/// character other than letters, digits, '-', '_' and '.' replaced by '_'.
std::string file_stem(size_t index, const std::string& name);

/// Writes an image of `channels` floats per pixel to DIR/RELATIVE (display_referred as in
/// sheafWriteImage); prints the error and returns its exit code on failure.
int write_report_image(const std::string& dir, const std::string& relative, int width, int height,
                       int channels, const std::vector<float>& pixels, bool display_referred);

/// Writes report.html, results.json and results.csv into DIR and, unless quiet, prints
/// "wrote DIR/report.html". Returns the exit code.
int write_report_texts(const std::string& dir, const std::string& html, const ResultsMeta& meta,
                       const std::vector<RunResult>& results, bool quiet);

} // namespace render
