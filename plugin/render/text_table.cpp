// Plain-text table layout.
#include "text_table.h"

#include <algorithm>

namespace render {

namespace {

std::string pad_left(const std::string& s, size_t width) {
    return s.size() >= width ? s : std::string(width - s.size(), ' ') + s;
}

std::string pad_right(const std::string& s, size_t width) {
    return s.size() >= width ? s : s + std::string(width - s.size(), ' ');
}

constexpr size_t kGap = 2;

} // namespace

std::string TextTable::str() const {
    size_t columns = header.size();
    for (const auto& row : rows) columns = std::max(columns, row.size());
    std::vector<size_t> width(columns, 0);
    auto measure = [&](const std::vector<std::string>& row) {
        for (size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
    };
    measure(header);
    for (const auto& row : rows) measure(row);
    // A group title wider than its columns widens the last of them.
    size_t column = 1;
    for (const auto& [title, span] : groups) {
        size_t total = 0;
        for (int i = 0; i < span && column + i < columns; ++i)
            total += width[column + i] + (i ? kGap : 0);
        if (title.size() + 4 > total && column + span - 1 < columns)
            width[column + span - 1] += title.size() + 4 - total;
        column += size_t(span);
    }
    auto line = [&](const std::vector<std::string>& row) {
        std::string out = "  ";
        for (size_t c = 0; c < columns; ++c) {
            const std::string cell = c < row.size() ? row[c] : "";
            if (c == 0)
                out += pad_right(cell, width[0]);
            else
                out += std::string(kGap, ' ') + pad_left(cell, width[c]);
        }
        while (!out.empty() && out.back() == ' ') out.pop_back();
        return out + "\n";
    };
    std::string out;
    if (!groups.empty()) {
        std::string g = "  " + std::string(width[0], ' ');
        column = 1;
        for (const auto& [title, span] : groups) {
            size_t total = 0;
            for (int i = 0; i < span && column + i < columns; ++i)
                total += width[column + i] + (i ? kGap : 0);
            const std::string label = " " + title + " ";
            const size_t dashes = total > label.size() ? total - label.size() : 0;
            g += std::string(kGap, ' ') + std::string(dashes / 2, '-') + label +
                 std::string(dashes - dashes / 2, '-');
            column += size_t(span);
        }
        out += g + "\n";
    }
    if (!header.empty()) out += line(header);
    for (const auto& row : rows) out += line(row);
    return out;
}

} // namespace render
