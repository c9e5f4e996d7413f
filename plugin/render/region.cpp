#include "region.h"

#include <cmath>
#include <cstdlib>

namespace render {
namespace {

// A POV-Ray row or column value: its edge in pixels, the top/left edge of the pixel for a
// start (0-based), just past it for an end.
int edge(const std::string& option, const std::string& text, int size, bool end) {
    char* stop = nullptr;
    const double v = std::strtod(text.c_str(), &stop);
    if (text.empty() || *stop != '\0' || !std::isfinite(v) || v < 0)
        throw RegionError(option + " " + text + ": expected a row or column from 1, or a "
                                                "fraction from 0.0 to 1.0");
    // As POV-Ray 3.7 reads them (checked against povray): a start below 1 and an end up to 1
    // are fractions of the image, cut down to a whole pixel; other values are row or column
    // numbers from 1 (+SR1 is the first row, +ER1 the whole image).
    const bool fraction = end ? v <= 1.0 : v < 1.0;
    if (fraction) return int(std::floor(v * size));
    if (std::floor(v) > size)
        throw RegionError(option + " " + text + ": past the image's " + std::to_string(size) +
                          (option.find("row") != std::string::npos ? " rows" : " columns"));
    return end ? int(v) : int(v) - 1; // POV-Ray drops a fraction of a row number
}

int positive(const std::string& text, const std::string& what) {
    char* stop = nullptr;
    const long v = std::strtol(text.c_str(), &stop, 10);
    if (text.empty() || *stop != '\0' || v < 1 || v > 1000000)
        throw RegionError("--tile: expected " + what + ", got '" + text + "'");
    return int(v);
}

void parse_tile(const std::string& tile, int& index, int& columns, int& rows) {
    const size_t slash = tile.find('/');
    if (slash == std::string::npos)
        throw RegionError("--tile " + tile + ": expected I/N (tile I of N, from 1) or I/CxR");
    index = positive(tile.substr(0, slash), "the tile's number from 1 before '/'");
    tile_grid(tile.substr(slash + 1), columns, rows);
    if (index > columns * rows)
        throw RegionError("--tile " + tile + ": there are " + std::to_string(columns * rows) +
                          " tiles, numbered from 1");
}

} // namespace

void tile_grid(const std::string& count, int& columns, int& rows) {
    const size_t x = count.find_first_of("xX");
    if (x != std::string::npos) {
        columns = positive(count.substr(0, x), "the columns of CxR");
        rows = positive(count.substr(x + 1), "the rows of CxR");
        return;
    }
    const int n = positive(count, "the number of tiles after '/'");
    rows = int(std::sqrt(double(n)));
    while (n % rows != 0) --rows;
    columns = n / rows;
}

PixelRect tile_rect(int index, int columns, int rows, int width, int height) {
    const int c = (index - 1) % columns, r = (index - 1) / columns;
    PixelRect p;
    p.x = int(int64_t(c) * width / columns);
    p.y = int(int64_t(r) * height / rows);
    p.width = int(int64_t(c + 1) * width / columns) - p.x;
    p.height = int(int64_t(r + 1) * height / rows) - p.y;
    return p;
}

void check_region_request(const RegionRequest& r) {
    if (r.tile && (r.start_row || r.end_row || r.start_column || r.end_column))
        throw RegionError("--tile and the rows and columns (+SR +ER +SC +EC) both name the part "
                          "to render; give one");
    resolve_region(r, 1 << 20, 1 << 20); // the form, on an image large enough for any pixel
}

PixelRect resolve_region(const RegionRequest& r, int width, int height) {
    if (r.tile) {
        int index = 0, columns = 0, rows = 0;
        parse_tile(*r.tile, index, columns, rows);
        if (columns > width || rows > height)
            throw RegionError("--tile " + *r.tile + ": a " + std::to_string(columns) + "x" +
                              std::to_string(rows) + " grid does not fit a " +
                              std::to_string(width) + "x" + std::to_string(height) + " image");
        return tile_rect(index, columns, rows, width, height);
    }
    const int x0 = r.start_column ? edge("--start-column", *r.start_column, width, false) : 0;
    const int x1 = r.end_column ? edge("--end-column", *r.end_column, width, true) : width;
    const int y0 = r.start_row ? edge("--start-row", *r.start_row, height, false) : 0;
    const int y1 = r.end_row ? edge("--end-row", *r.end_row, height, true) : height;
    if (x0 >= x1)
        throw RegionError("the columns " + std::to_string(x0 + 1) + " to " + std::to_string(x1) +
                          " (+SC +EC) leave nothing of the image to render");
    if (y0 >= y1)
        throw RegionError("the rows " + std::to_string(y0 + 1) + " to " + std::to_string(y1) +
                          " (+SR +ER) leave nothing of the image to render");
    return {x0, y0, x1 - x0, y1 - y0};
}

} // namespace render
