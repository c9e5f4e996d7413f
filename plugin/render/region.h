// The part of the image render computes: POV-Ray's +SR/+ER/+SC/+EC (rows and columns from 1,
// or fractions of the image) and --tile I/N, turned into the library's region.* settings once
// the frame's size is known.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

namespace render {

/// What the command line asked for; all empty: the whole image.
struct RegionRequest {
    std::optional<std::string> start_row, end_row, start_column, end_column; ///< POV-Ray's
    std::optional<std::string> tile; ///< "I/N" or "I/CxR", I from 1
    bool any() const { return start_row || end_row || start_column || end_column || tile; }
};

/// Pixels of the image, x and y from 0 at the top left.
struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0;
};

struct RegionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Checks the request's form (numbers, I/N) before any scene is read; throws RegionError.
void check_region_request(const RegionRequest& r);

/// The pixels of a `width` x `height` image the request names, as POV-Ray 3.7 reads them: a
/// start below 1 and an end up to 1 are fractions of the image (a fraction f is the edge
/// floor(f * size), so +SR0.5 starts where +ER0.5 ends); other values are rows or columns from
/// 1, the end one included (+SR1 is the first row, +ER1 the whole image). Tile I of N cuts
/// the image into C x R tiles (C * R = N, as square as N allows, C >= R; or as given by
/// I/CxR), numbered from 1 along rows from the top left. Throws RegionError when the part is
/// empty or leaves the image.
PixelRect resolve_region(const RegionRequest& r, int width, int height);

/// The columns and rows of tile I/N: "16" -> 4 x 4, "8" -> 4 x 2, "3x2" -> 3 x 2. Throws
/// RegionError on a malformed count.
void tile_grid(const std::string& count, int& columns, int& rows);

/// Tile `index` (from 1) of a grid of `columns` x `rows` over a `width` x `height` image:
/// column c spans [c * width / columns, (c + 1) * width / columns).
PixelRect tile_rect(int index, int columns, int rows, int width, int height);

} // namespace render
