// height_field { png "file" | pgm ... | function W, H { ... }  smooth  water_level L
// hierarchy  modifiers }: POV-Ray's height field, built as a triangle mesh over the unit square
// (x and z in [0, 1], the height in [0, 1] along y; the image's bottom row at z = 0). Heights
// come from a grey image (its value), an 8-bit palette PNG (its index over 255, as POV-Ray
// reads such files, through libpng), or a function of (x, y, 0) over a W x H grid (y = 1
// at the far edge, as an image's top row).
// Colour images are warned and left out (POV-Ray reads their red and green as one 16-bit
// height, which Sheaf does not).
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace sheaf::io::pov {

namespace {

/// The most samples a height field may have (a 4096 x 4096 image).
constexpr size_t kMaxHeightSamples = size_t(4096) * 4096;

} // namespace

bool Parser::parse_height_field(const Token& kw, PovObject& o) {
    expect_sym("{");
    std::vector<float> heights; // row-major, row 0 at z = 0
    int w = 0, h = 0;
    bool colour_image = false;
    static const std::set<std::string> types = {"gif",  "tga",  "iff", "ppm", "pgm", "png",
                                                "jpeg", "tiff", "exr", "hdr", "bmp"};
    const Token& src = peek();
    if (accept_kw("function")) {
        const Token& at = peek();
        const double fw = parse_float();
        accept_sym(",");
        const double fh = parse_float();
        if (!(fw >= 2 && fh >= 2 && fw * fh <= double(kMaxHeightSamples)))
            error_at(at, "a height field function's grid must be at least 2 x 2 and at most " +
                             std::to_string(kMaxHeightSamples) + " samples");
        w = int(fw), h = int(fh);
        const Value v = parse_function(src);
        const auto fn = std::static_pointer_cast<const PovFunction>(v.ptr);
        if (!fn->scene_unsupported.empty()) {
            unsupported(src, "height_field of a " + fn->scene_unsupported + " (left out)");
            skip_rest_of_block();
            return false;
        }
        charge(size_t(w) * size_t(h) * sizeof(float), at);
        heights.resize(size_t(w) * size_t(h));
        uint64_t left = function_terms_left();
        const uint64_t had = left;
        try {
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i) {
                    // As an image: the function's y runs from the far edge (z = 1) down.
                    const double args[3] = {double(i) / (w - 1), 1 - double(j) / (h - 1), 0};
                    heights[size_t(j) * size_t(w) + size_t(i)] =
                        float(fn->eval(args, fn->params.size() == 3 ? 3 : 0, left));
                }
        } catch (const FnStepsExceeded&) {
            too_many_function_terms(src);
        }
        count_function_terms(had - left);
    } else {
        const Token& type = peek();
        if (accept_kw("pot") || accept_kw("sys")) { // Fractint's and the system's formats
            parse_string();
            unsupported(type, "height_field from a " + type.text + " file (left out)");
            skip_rest_of_block();
            return false;
        }
        if (peek().kind == TokKind::Ident && types.count(peek().text)) advance();
        const Token& name = peek();
        const std::string file = parse_string();
        const std::string path = find_file(file, name, "image file",
                                           {".png", ".pgm", ".ppm", ".tga", ".tif", ".tiff", ".exr",
                                            ".hdr", ".gif", ".jpg", ".jpeg", ".bmp"});
        if (!options_.read_raster)
            error_at(name, "height_field image '" + file + "': this program reads no images");
        Raster img;
        try {
            img = options_.read_raster(path, kMaxHeightSamples);
        } catch (const RenderError& e) {
            error_at(name, "cannot read image file '" + file + "': " + e.what());
        }
        w = img.width, h = img.height;
        const size_t nc = size_t(img.channels);
        charge(img.pixels.size() * sizeof(float), name);
        heights.resize(size_t(w) * size_t(h));
        for (int row = 0; row < h; ++row)
            for (int i = 0; i < w; ++i) {
                const float* p = &img.pixels[(size_t(row) * size_t(w) + size_t(i)) * nc];
                if (nc >= 3 && (p[1] != p[0] || p[2] != p[0])) colour_image = true;
                // The image's top row is the far edge (z = 1).
                heights[size_t(h - 1 - row) * size_t(w) + size_t(i)] = p[0];
            }
        if (colour_image) {
            unsupported(src, "height_field from a colour image (left out; grey and 8-bit "
                             "palette images are read)");
            skip_rest_of_block();
            return false;
        }
    }
    bool smooth = false, texture_here = false;
    float water = 0;
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (accept_kw("smooth")) {
            smooth = parse_bool_opt(true);
        } else if (accept_kw("water_level")) {
            water = float(parse_float());
        } else if (accept_kw("hierarchy") || accept_kw("premultiplied")) {
            parse_bool_opt(true);
        } else if (!parse_modifier(o, texture_here)) {
            error_expected(t, "smooth, water_level, hierarchy, a modifier or '}'");
        }
    }
    // POV-Ray keeps heights as 16-bit values: a function's are clamped to [0, 1].
    for (float& v : heights) v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
    auto mesh = std::make_shared<Mesh>();
    const size_t n = size_t(w) * size_t(h);
    charge(n * sizeof(Vec3) * (smooth ? 2 : 1) + size_t(w - 1) * size_t(h - 1) * 6 * 4, src);
    mesh->positions.resize(n);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            mesh->positions[size_t(j) * size_t(w) + size_t(i)] =
                Vec3(float(i) / float(w - 1), heights[size_t(j) * size_t(w) + size_t(i)],
                     float(j) / float(h - 1));
    auto at = [&](int i, int j) { return uint32_t(size_t(j) * size_t(w) + size_t(i)); };
    for (int j = 0; j + 1 < h; ++j)
        for (int i = 0; i + 1 < w; ++i) {
            const uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            const float top = std::max({heights[a], heights[b], heights[c], heights[d]});
            if (top <= water && water > 0) continue; // under the water level: left out
            for (uint32_t k : {a, c, b, a, d, c}) mesh->indices.push_back(k);
        }
    if (smooth) { // area-weighted vertex normals
        mesh->normals.assign(n, Vec3(0, 0, 0));
        for (size_t t = 0; t + 2 < mesh->indices.size(); t += 3) {
            const uint32_t* k = &mesh->indices[t];
            const Vec3 fn = cross(mesh->positions[k[1]] - mesh->positions[k[0]],
                                  mesh->positions[k[2]] - mesh->positions[k[0]]);
            for (int e = 0; e < 3; ++e) mesh->normals[k[e]] += fn;
        }
        for (Vec3& v : mesh->normals) v = length(v) > 0 ? normalize(v) : Vec3(0, 1, 0);
    }
    if (mesh->indices.empty()) {
        unsupported(kw, "height_field entirely under its water level (left out)");
        return false;
    }
    o.kind = PovKind::Mesh;
    o.mesh = std::move(mesh);
    return true;
}

} // namespace sheaf::io::pov
