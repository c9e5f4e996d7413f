// Plain-text tables for the terminal: the first column left-aligned, the others right-aligned,
// and an optional line of group titles spanning several columns ("--- crsh ---").
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace render {

struct TextTable {
    /// Titles over column groups: (title, columns spanned), starting at column 1.
    std::vector<std::pair<std::string, int>> groups;
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;

    /// The table, each line indented by two spaces and ending in a newline.
    std::string str() const;
};

} // namespace render
