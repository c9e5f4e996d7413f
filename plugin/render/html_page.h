// The HTML report's page frame and shared pieces: head with the inline style sheet, headings,
// tables of the papers' statistics and the settings, all self-contained (no scripts, no
// network, no external fonts).
#pragma once

#include "results_files.h"
#include "run_result.h"

#include <string>
#include <vector>

namespace render {

/// <!DOCTYPE html> through <body> and the title block (scene, command, version).
std::string page_begin(const std::string& title, const ResultsMeta& meta);
/// The closing tags.
std::string page_end();

/// One HTML table of rows x columns; cells are escaped; the first row is the header. `classes`
/// (when not empty) gives a class per row.
std::string html_table(const std::vector<std::vector<std::string>>& rows,
                       const std::vector<std::string>& classes = {});

/// Per ray type: tests/hits/misses per level and result, with total and share of brute force.
std::string html_type_tables(const std::vector<RunResult>& results);

/// Keys down, results across; values that differ between results are marked.
std::string html_settings_table(const std::vector<RunResult>& results);

} // namespace render
