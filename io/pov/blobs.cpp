// blob { threshold T  sphere { <C>, R, [strength] S ... }  cylinder { <B>, <E>, R,
// [strength] S ... }  component S, R, <C>  modifiers }: the blob shape of
// core/geometry/blob.h, exact. A component's transforms place it within the blob; its own
// texture is not blended as POV-Ray blends them: the blob's texture is used, or, when the blob
// has none, the first one given; when every component has the same one, that one.
#include "io/pov/parser.h"

#include "core/base/error.h"
#include "core/geometry/blob_build.h"

#include <optional>

namespace sheaf::io::pov {

bool Parser::parse_blob(const Token& kw, PovObject& o) {
    expect_sym("{");
    auto blob = std::make_shared<BlobModel>();
    // The components' textures: the first one's, the first given, and where they first differ.
    PovTextureRef first_texture, given;
    size_t components = 0;
    std::optional<Token> differ_at;
    auto note_texture = [&](const Token& at, const PovTextureRef& t) {
        if (components++ == 0) first_texture = t;
        if (!given) given = t;
        if (!same_texture(t, first_texture) && !differ_at) differ_at = at;
    };
    auto component = [&](const Token& at, auto&& add) {
        charge(sizeof(BlobElement), at);
        try {
            add();
        } catch (const BlobError& e) {
            error_at(at, e.what());
        }
    };
    // A component's modifiers and closing brace: its placement, its texture noted.
    auto modifiers = [&](const Token& at, Affine& placement) {
        PovObject scratch;
        scratch.where = at;
        bool texture_here = false;
        parse_object_modifiers(scratch, texture_here);
        placement = scratch.local;
        note_texture(at, scratch.texture);
    };
    auto strength = [&]() {
        accept_sym(",");
        accept_kw("strength");
        return float(parse_float());
    };
    bool texture_here = false;
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (accept_kw("threshold")) {
            const Token& at = peek();
            const double v = parse_float();
            if (!(v > 0) || !std::isfinite(v))
                error_at(at, "a blob's threshold must be a positive, finite number");
            blob->threshold = float(v);
        } else if (accept_kw("sphere")) {
            expect_sym("{");
            const Vec3 c = parse_vector();
            accept_sym(",");
            const float r = float(parse_float());
            const float s = strength();
            Affine placement;
            modifiers(t, placement);
            component(t, [&] { add_blob_sphere(*blob, c, r, s, placement); });
        } else if (accept_kw("cylinder")) {
            expect_sym("{");
            const Vec3 a = parse_vector();
            accept_sym(",");
            const Vec3 b = parse_vector();
            accept_sym(",");
            const float r = float(parse_float());
            const float s = strength();
            Affine placement;
            modifiers(t, placement);
            component(t, [&] { add_blob_cylinder(*blob, a, b, r, s, placement); });
        } else if (accept_kw("component")) { // POV-Ray 3.0: component S, R, <C>
            const float s = float(parse_float());
            accept_sym(",");
            const float r = float(parse_float());
            accept_sym(",");
            const Vec3 c = parse_vector();
            note_texture(t, nullptr);
            component(t, [&] { add_blob_sphere(*blob, c, r, s, Affine()); });
        } else if (!parse_modifier(o, texture_here)) {
            error_expected(t, "a blob component (sphere, cylinder, component), a modifier or '}'");
        }
    }
    if (blob->elements.empty()) { // nothing can be inside (POV-Ray refuses it)
        unsupported(kw, "blob without components (left out)");
        return false;
    }
    // The components' texture was given in the blob's space, before the blob's transforms.
    if (given && !differ_at) {
        o.texture = transformed(given, o.local);
    } else if (given) {
        unsupported(*differ_at, "blob component textures that differ (not blended; the "
                                "blob's texture is used, or else the first one given)");
        if (!o.texture) o.texture = transformed(given, o.local);
    }
    o.kind = PovKind::Shape;
    o.shape.kind = ShapeKind::Blob;
    o.blob = std::move(blob);
    return true;
}

} // namespace sheaf::io::pov
