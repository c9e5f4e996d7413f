// The parser shared by the reader's parts: the token stream with its directives and macros
// (token_stream.cpp, directives.cpp, macros.cpp, files.cpp), expressions (expressions.cpp,
// builtins.cpp, functions_parse.cpp), objects (objects.cpp, meshes.cpp), textures
// (textures.cpp), camera, lights and settings (camera_lights.cpp). One instance reads one scene.
#pragma once

#include "io/font/font.h"
#include "io/pov/function.h"
#include "io/pov/lexer.h"
#include "io/pov/model.h"
#include "io/pov/pov_reader.h"
#include "io/pov/scopes.h"
#include "io/pov/splines.h"
#include "io/pov/value.h"

#include <cstdint>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace sheaf::io::pov {

/// Limits: exceeding one is a SceneError at the offending position, never a hang.
constexpr int kMaxMacroDepth = 200;
constexpr int kMaxIncludeDepth = 64;
constexpr size_t kMaxArrayElements = 100'000'000;
/// The budgets of work and memory are PovLimits (pov_reader.h). Objects count twice: as they
/// are parsed, temporaries included (objects inside a union are not placed, and charged to the
/// data budget, until it closes, so an endless loop inside one grew without bound), and against
/// the data budget as they are placed or a CSG takes them.
/// Nested expressions, objects, textures and function bodies: the parser recurses into each,
/// so a deeper nesting is refused before the stack runs out (about 3 KB a level: 500 levels
/// need 1.5 MB of the 64 MiB the readers run on, core/base/stack.h, whatever the calling
/// thread's stack).
constexpr int kMaxNesting = 500;
/// A function body's tree, which is evaluated (and freed) recursively.
constexpr int kMaxFunctionHeight = 10'000;
/// Array dimensions, as POV-Ray's own limit.
constexpr size_t kMaxArrayDimensions = 5;

struct ObjectProbe;   // io/pov/probe.h
struct FunctionScene; // io/pov/function_scene.h

struct Macro {
    std::shared_ptr<const TokenFile> file;
    size_t body = 0; // index of the first body token
    /// Shared, so that a call holds them without a copy while its arguments (which may
    /// redefine the macro) are parsed.
    std::shared_ptr<const std::vector<uint32_t>> params; // the parameters' names (Scopes)
};

/// An open #fopen file.
struct PovFileHandle {
    bool reading = false;
    std::shared_ptr<const TokenFile> tokens; // reading: the file's tokens
    size_t pos = 0;
    std::shared_ptr<std::ofstream> out; // writing
};

/// The affine map whose columns are c0, c1, c2 and whose translation is `o` (objects.cpp).
Affine frame(Vec3 o, Vec3 c0, Vec3 c1, Vec3 c2);
/// Unit vectors u, v with (u, v, w) right-handed and orthonormal; w must be unit length.
void basis(Vec3 w, Vec3& u, Vec3& v);

class Parser {
  public:
    explicit Parser(const PovOptions& options);
    /// Parses the scene file at `path` into `model`.
    void parse_scene(const std::string& path);

    PovModel model;
    std::vector<std::string> warnings;

    // ---- token stream (token_stream.cpp) ----
    struct Cond {
        enum Kind { If, While, For, Switch } kind = If;
        size_t pos = 0;                 // While: the condition; For: the body
        uint32_t var = Scopes::kNoName; // For: the loop variable's name
        double end = 0, step = 1;
        uint64_t iterations = 0;
        Token where;
    };
    struct Frame {
        std::shared_ptr<const TokenFile> file;
        size_t pos = 0;
        bool macro = false;
        bool own_scope = false;
        std::vector<Cond> conds;
        Token where; // the include or the call
    };
    const Token& raw() const { return frames_.back().file->tokens[frames_.back().pos]; }
    void advance();
    /// The next token after running directives, expanding macros and leaving finished files.
    const Token& peek();
    const Token& peek_expanded();      // peek's work, without its memory of the last answer
    const Token& peek_cont_expanded(); // the same for peek_cont
    /// The token peek last returned and where the stream stood then.
    struct Peeked {
        const Token* token = nullptr;
        uint64_t steps = 0;
        size_t depth = 0, pos = 0;
        const TokenFile* file = nullptr;
        explicit operator bool() const { return token != nullptr; }
        int directive_args = 0;
    } peeked_, peeked_cont_;
    /// The next token for an expression that may continue: only closes #if/#switch branches,
    /// macros and files; any other directive ends the expression.
    const Token& peek_cont();
    Token next();
    bool is_sym(const char* s) { return is_sym_tok(peek(), s); }
    bool is_kw(const char* s) { return is_kw_tok(peek(), s); }
    static bool is_sym_tok(const Token& t, const char* s) {
        return t.kind == TokKind::Symbol && same_text(t.text, s);
    }
    static bool is_kw_tok(const Token& t, const char* s) {
        return t.kind == TokKind::Ident && same_text(t.text, s);
    }
    /// a == s, inline: the reader compares every token it peeks at with short literals.
    static bool same_text(const std::string& a, const char* s) {
        const char* p = a.c_str(); // NUL-terminated; a NUL inside `a` ends neither early
        const size_t n = a.size();
        size_t i = 0;
        for (; i < n; ++i)
            if (p[i] != s[i] || s[i] == 0) return false;
        return s[i] == 0;
    }
    /// What an identifier that names no variable is among the words expressions know.
    enum class Word : uint8_t { Unknown, Other, Colour, MathBuiltin, Builtin };
    Word word(const Token& t);
    std::vector<Word> words_; // by name (Scopes), computed on first sight
    bool accept_sym(const char* s);
    bool accept_kw(const char* s);
    void expect_sym(const char* s, const std::string& expected = "");
    std::string expect_ident(const std::string& expected);
    std::string where(const Token& t) const;
    /// Where the reader is: one line per macro call and include below the scene file,
    /// innermost first ("\n  in macro 'M' called at FILE:LINE:COL"), for error messages.
    std::string context() const;
    [[noreturn]] void error_expected(const Token& found, const std::string& expected) const;
    [[noreturn]] void error_at(const Token& t, const std::string& msg) const;
    void warn(const Token& t, const std::string& msg);
    void unsupported(const Token& t, const std::string& what);
    /// What Sheaf draws otherwise than POV-Ray: `FILE:LINE:COL: warning: approximated WHAT`
    /// (an error with `strict`). A scene with only these is still clean (`render --check`);
    /// inside a declaration it waits, as unsupported() does, until the value is used.
    void approximated(const Token& t, const std::string& what);
    /// The warning for a layered texture lit with one finish (io/pov/textures.cpp).
    void warn_layers_lit_alike(const Token& t);
    /// Reports the unsupported features a declared value carries (see PendingWarning).
    void raise_pending(const Value& v);
    /// While a #declare is read, unsupported features are collected here instead.
    std::vector<std::vector<PendingWarning>> captures_;
    /// Skips a balanced { ... } block (directives inside still run).
    void skip_block();
    /// Skips up to and including the '}' closing a block already entered.
    void skip_rest_of_block();
    void push_file(const std::string& path, const Token& where);
    bool in_macro_or_include() const { return frames_.size() > 1; }

    // ---- symbols ----
    const Value* lookup(const std::string& name) const;
    Value* lookup_mut(const std::string& name);
    /// The same for an identifier token, by the number it was read with.
    const Value* lookup(const Token& t) const;
    Value* lookup_mut(const Token& t);
    void declare(const std::string& name, Value v, bool local);
    /// The same by the name's number (Scopes::intern).
    void declare(uint32_t name, Value v, bool local);
    /// #local in scope `scope`: its own variable, or the one a by-reference parameter of
    /// that name stands for.
    void declare_in(size_t scope, const std::string& name, Value v);
    const Macro* find_macro(const std::string& name) const;
    const Macro* find_macro(const Token& t) const;

    // ---- directives (directives.cpp, macros.cpp, files.cpp) ----
    /// Runs the directive at '#'. In continuation mode only the ones that close a branch run;
    /// for any other, returns false and consumes nothing.
    bool directive(bool continuation);
    void skip_to_branch(const Token& from);
    Token next_directive_in_block(const Token& from, const char* missing_end);
    void declare_directive(bool local);
    void define_macro(const Token& where);
    void call_macro(const Token& name, const Macro& m);
    void undef_directive();
    void ifdef_directive(bool want_defined);
    void include_directive(const Token& where);
    std::string find_include(const std::string& name, const Token& where) const;
    /// A file the scene names (include, image): its folder, the include paths, then POV-Ray's
    /// standard include folder; an error naming `what` when it is nowhere. A name without an
    /// extension is also tried with each of `extensions`, in order.
    std::string find_file(const std::string& name, const Token& where, const std::string& what,
                          const std::vector<std::string>& extensions = {}) const;
    void fopen_directive(const Token& where);
    void read_directive(const Token& where);
    void write_directive(const Token& where);
    void default_directive();
    void version_directive();

    // ---- expressions (expressions.cpp, builtins.cpp, functions_parse.cpp) ----
    Value parse_expr();
    double parse_float();
    Vec3 parse_vector();
    Color5 parse_color();
    bool parse_bool_opt(bool dflt); // an optional boolean after a flag keyword
    std::string parse_string();
    /// Anything a #declare or a macro argument may hold: objects, textures, expressions...
    Value parse_rvalue();
    bool starts_expression(const Token& t) const;
    Value parse_ternary();
    Value parse_or();
    Value parse_and();
    Value parse_compare();
    Value parse_additive();
    Value parse_term();
    Value parse_unary();
    Value parse_postfix();
    Value parse_primary();
    Value parse_identifier(const Token& t);
    Value parse_color_keyword(const Token& t);
    Value parse_array_literal(const Token& t);
    Value parse_array_init(const std::vector<size_t>& sizes, const Token& t);
    Value index_value(const Value& base, const Token& t);
    bool builtin_call(const Token& t, Value& out);
    Value call_function(const Token& t, const PovFunction& f);
    /// S(t [, TYPE]) after a spline's name: its point at t (io/pov/splines.cpp).
    Value call_spline(const PovSpline& s);
    bool accept_spline_kind(SplineKind& kind);
    Value parse_function(const Token& t);
    /// `internal(N)` and `pattern { ... }` as a function's whole body (into `f`).
    void parse_internal_function(PovFunction& f);
    void parse_pattern_function(PovFunction& f);
    void parse_pigment_function(PovFunction& f);
    /// A pigment function's pigment or a pattern function's pattern in a scene of its own, for
    /// the language's evaluation of the function.
    std::shared_ptr<const FunctionScene> function_scene(const Token& at, const PovPigment* pigment,
                                                        const PatternFunction* pattern);
    FnNode parse_fn(const std::vector<std::string>& params, int level);
    FnNode parse_fn_primary(const std::vector<std::string>& params);
    FnNode parse_fn_atom(const std::vector<std::string>& params);
    std::string fn_unsupported_;       // what the function being compiled uses that is unsupported
    std::string fn_scene_unsupported_; // ... and that the language cannot evaluate
    /// If the next token is a declared identifier (an array element with its indices) of
    /// type `t`, consumes it into `out`. A declared identifier of another type is an error
    /// naming `expected`.
    bool accept_declared(VType t, Value& out, const std::string& expected);
    /// If the next token is a declared identifier, consumes it (and its indices) into `out`.
    bool accept_declared_any(Value& out);
    int no_gt_ = 0;          // inside < >: '>' closes the vector
    int no_lt_ = 0;          // a poly's order: '<' opens its coefficients (poly { 4 <...)
    int directive_args_ = 0; // parsing a directive's condition: peek_cont runs no directive
    /// A directive's condition (#if, #while ...): parsed without running later directives.
    Value parse_condition();

    // ---- objects (objects.cpp, meshes.cpp) ----
    bool is_object_start(const Token& t) const;
    /// Parses an object; false (after a warning) for an unsupported kind, skipped.
    bool parse_object(PovObject& out);
    /// Parses modifiers up to and including the closing '}'.
    void parse_object_modifiers(PovObject& o, bool& texture_here);
    /// One modifier (transform, texture, flag ...); false when the next token is not one.
    bool parse_modifier(PovObject& o, bool& texture_here);
    /// bounded_by { objects } after its keyword, into o.bounded_by.
    void parse_bounded_by(PovObject& o);
    void parse_clipped_by(const Token& kw, PovObject& o);
    bool parse_transform_item(Affine& m);
    Affine parse_transform_block();
    void apply_transform(PovObject& o, const Affine& m);
    void parse_shape(const Token& kw, PovObject& o);
    /// '{' an object or object identifier, modifiers '}' (object { }, looks_like { }).
    bool parse_object_block(PovObject& o);
    /// quadric, cubic, quartic, poly; false (after a warning) for a poly above order 4.
    bool parse_poly(const Token& kw, PovObject& o);
    /// '<' exactly `count` float coefficients '>'.
    std::vector<double> parse_coefficients(const Token& kw, size_t count);
    void parse_csg(const Token& kw, PovObject& o);
    /// prism { ... }: a glyph shape swept along y; false (after a warning) for conic_sweep.
    bool parse_prism(const Token& kw, PovObject& o);
    bool parse_lathe(const Token& kw, PovObject& o);
    bool parse_sor(const Token& kw, PovObject& o);
    /// blob { threshold, components, modifiers } (io/pov/blobs.cpp).
    bool parse_blob(const Token& kw, PovObject& o);
    bool parse_isosurface(const Token& kw, PovObject& o);
    bool parse_julia_fractal(const Token& kw, PovObject& o);
    bool parse_height_field(const Token& kw, PovObject& o);
    /// A bicubic_patch as a smooth mesh (io/pov/bicubic_patches.cpp); false when degenerate.
    bool parse_bicubic_patch(const Token& kw, PovObject& o);
    bool parse_sphere_sweep(const Token& kw, PovObject& o);
    /// N 2-D points <r, h> of a lathe or sor, charged to the data budget first; `where`: each
    /// point's first token, for errors about it.
    std::vector<Vec3> parse_profile_points(const Token& count_at, int n, const char* what,
                                           std::vector<Token>& where);
    /// A lathe's or sor's count of points: a whole number of at least `minimum`.
    int parse_profile_count(const Token& count_at, int minimum, const char* what);
    /// text { ttf FONT STRING THICKNESS, OFFSET modifiers }: a union of glyph shapes.
    void parse_text(const Token& kw, PovObject& o);
    FontCache fonts_; // text's fonts
    /// The probes trace() and inside() built, most recent last, each with the object it was
    /// built from (held, so that its address is not reused by another).
    std::vector<std::pair<std::shared_ptr<void>, std::shared_ptr<const ObjectProbe>>> probes_;
    /// The probe of object value `v` (built on its first query).
    const ObjectProbe& probe(const Value& v, const Token& at); // for trace() and inside() at `at`
    void parse_triangle(const Token& kw, PovObject& o, bool smooth);
    void parse_mesh(const Token& kw, PovObject& o);
    void parse_mesh2(const Token& kw, PovObject& o);
    /// After a mesh's '{': a declared mesh and the modifiers after it (then the block is
    /// read); false when no identifier comes.
    bool accept_declared_mesh(PovObject& o);
    /// texture_list { N, texture {...} ... } (mesh2).
    std::vector<PovTextureRef> parse_texture_list();
    /// mesh_camera { RAYS, DISTRIBUTION [, MAX_DISTANCE] mesh {...}... [smooth] }.
    void parse_mesh_camera(const Token& kw, PovCamera& c);
    void parse_polygon(const Token& kw, PovObject& o);
    size_t objects_made_ = 0;
    /// What one object (not the objects inside it) adds to the data budget: the object and
    /// its texture when no other object shares it.
    static size_t object_bytes(const PovObject& o);

    // ---- textures (textures.cpp, pigments.cpp, normals.cpp, patterns.cpp) ----
    /// After 'texture': one { ... } block, on top of `base`.
    PovTextureRef parse_texture_block(const PovTexture& base);
    /// After 'texture': the block and any further 'texture' blocks, layered (later ones on top).
    PovTextureRef parse_texture_layers(const PovTexture& base);
    PovTexture parse_texture_body(const PovTexture& base, const char* close);
    std::vector<std::pair<double, PovTextureRef>> parse_texture_map();
    /// After 'pigment': { ... } on top of `base`.
    std::shared_ptr<const PovPigment> parse_pigment(const PovPigment& base);
    void parse_pigment_body(PovPigment& p, const char* close);
    std::vector<PovMapEntry> parse_color_map();
    std::vector<PovMapEntry> parse_pigment_map();
    void parse_image_map(const Token& kw, PovPigment& p);
    /// An image block's [type] "file" (after its '{'), found on the include paths.
    std::shared_ptr<PovImage> parse_image_file(const Token& kw);
    /// The items image_map and bump_map share (map_type, once, interpolate, use_color), read
    /// into img; false (nothing read) for any other.
    bool parse_image_item(PovImage& img);
    /// image_pattern's block, after the keyword kw: { [type] "file" image items }.
    std::shared_ptr<const PovImage> parse_image_pattern(const Token& kw);
    /// bump_map { [type] "file" map_type once interpolate use_color use_index bump_size }.
    void parse_bump_map(const Token& kw, PovNormal& n);
    /// After 'normal': { ... } on top of `base` (may be null); null when it changes nothing.
    std::shared_ptr<const PovNormal> parse_normal(const PovNormal* base);
    void parse_normal_body(PovNormal& n, bool& have, const char* close);
    std::vector<std::pair<double, std::shared_ptr<const PovNormal>>>
    parse_normal_map(const Token& kw, bool weights);
    std::shared_ptr<const PovNormal> map_entry(const Token& at,
                                               std::shared_ptr<const PovNormal> entry);
    std::vector<std::array<double, 3>> parse_slope_map();
    bool is_pattern_name(const Token& t) const;
    /// A pattern keyword and its arguments; `list` gets the entries a list pattern takes and
    /// `supported` whether Sheaf can show it. False (nothing read) when no pattern is next.
    bool parse_pattern_name(PovPattern& pt, int& list, bool& supported);
    /// A pattern modifier (turbulence, frequency, waves, warp ...) or a transform (into local).
    /// The arguments of `mandel`, `julia` or `magnet` (`keyword`): mandel's iterations,
    /// julia's constant and iterations, a magnet's type, mandel or julia and theirs
    /// (io/pov/fractal_patterns.cpp).
    void parse_fractal(PovPattern& pt, const std::string& keyword);
    /// `exponent N`, `interior TYPE, FACTOR` or `exterior TYPE, FACTOR` after its keyword.
    void parse_fractal_modifier(const Token& keyword, FractalParams& f);
    /// The slope pattern's direction (or point_at point), ranges and altitude after its
    /// `keyword` (io/pov/slope_pattern.cpp).
    void parse_slope(PovPattern& pt, const Token& keyword);
    /// density_file's `df3 "file"` after its keyword: the voxels read
    /// (io/pov/density_file.cpp).
    std::shared_ptr<const PovDensity> parse_density_file(const Token& keyword);
    bool parse_pattern_modifier(PovPattern& pt, Affine& local);
    /// A turbulence's `octaves` (patterns, warps, fog): clamped to 1..10 as POV-Ray does,
    /// a value that is not a number taking 1.
    int parse_octaves();
    /// An error at `t` when pattern `pt` is one only normals take (facets), met elsewhere.
    void only_in_normals(const Token& t, const PovPattern& pt) const;
    void parse_warp(PovPattern& pt, const Affine& local); // after `warp`
    void skip_to_block_end(); // after '{' was read: up to and including its '}'
    bool is_color_start(const Token& t);
    /// Whether a map entry (`[value ...]`) starts with its value: a number, a declared float
    /// (which is_color_start also accepts, as floats promote to colours), or another
    /// expression that is not a colour; average maps may leave the value out.
    bool starts_map_value(const Token& t);
    void parse_finish(PovFinish& f);
    PovInterior parse_interior(const PovInterior& base);
    PovMedia parse_media();
    /// spline { [TYPE] TIME, POINT … } after `spline`, or a declared one extended.
    PovSpline parse_spline();
    void parse_scattering(PovMedia& m);
    PovPigment parse_density();
    PovTexture current_default() const { return model.default_texture; }

    // ---- camera, lights, settings (camera_lights.cpp) ----
    void parse_camera(PovCamera& c);
    void parse_light(const Token& kw, PovObject& o);
    void parse_global_settings();
    void parse_radiosity();
    /// A radiosity value within the settings registry's range of `key`; larger ones are
    /// clamped with a warning.
    double radiosity_in_range(const Token& at, const std::string& name, std::string_view key,
                              double v);
    void parse_background();
    void parse_atmospheric(const Token& kw);
    void parse_rainbow(const Token& kw);
    // photons.cpp: the scene's, an object's and a light's photon blocks.
    void parse_photon_settings();
    void parse_object_photons(PovObject& o);
    void parse_light_photons(Light& l);
    PovSky parse_sky_sphere(); // after the keyword sky_sphere
    bool parse_statement();    // one top-level item; false at the end of the scene

    // ---- work ----
    uint64_t steps_ = 0; // against options_.limits.parse_steps
    /// What the scene has used of options_.limits so far.
    PovUsage usage() const {
        return {steps_, objects_made_, peak_data_bytes_, loop_runs_, macro_calls_, function_terms_};
    }
    uint64_t macro_calls_ = 0;    // against limits.macro_calls
    uint64_t function_terms_ = 0; // against limits.function_terms (and parse_steps)
    uint64_t loop_runs_ = 0;      // runs of all loops together, against limits.loop_iterations
    size_t peak_data_bytes_ = 0;
    /// The steps left before limits.parse_steps (for a function's evaluation to count down).
    uint64_t steps_left() const {
        return options_.limits.parse_steps - std::min(steps_, options_.limits.parse_steps);
    }
    /// One more object parsed (`count`: a sweep's pieces); an error at `at` past limits.objects.
    void count_objects(const Token& at, size_t count = 1);
    [[noreturn]] void too_many_steps(const Token& at) const;
    /// The terms a function evaluated while the scene is read may take: the fewer of the
    /// parse steps and the function terms left.
    uint64_t function_terms_left() const;
    /// Counts `terms` evaluated, as function terms and as parse steps.
    void count_function_terms(uint64_t terms) { steps_ += terms, function_terms_ += terms; }
    /// The error at `at` when an evaluation ran out of function_terms_left(): names the limit
    /// that ran out.
    [[noreturn]] void too_many_function_terms(const Token& at) const;
    int nesting_ = 0;
    /// One level of a nested construct, from `at` to the end of its scope; an error at `at`
    /// past kMaxNesting.
    class Nest {
      public:
        Nest(Parser& p, const Token& at) : p_(p) {
            if (++p_.nesting_ > kMaxNesting) {
                --p_.nesting_;
                p_.error_at(at, "nested deeper than " + std::to_string(kMaxNesting) +
                                    " levels (expressions, objects and textures together)");
            }
        }
        ~Nest() { --p_.nesting_; }
        Nest(const Nest&) = delete;
        Nest& operator=(const Nest&) = delete;

      private:
        Parser& p_;
    };

    // ---- files and random streams ----
    std::string scene_dir_;
    std::vector<std::string> file_names_;
    std::vector<uint32_t> rand_streams_; // seed() streams: POV-Ray's 32-bit state
    size_t data_bytes_ =
        0; // live arrays and strings, objects placed or in a CSG: limits.data_bytes
    void charge(size_t bytes, const Token& t);

    // ---- state ----
    PovOptions options_;
    std::vector<Frame> frames_;
    /// The variables. A macro's parameters passed by reference (an argument that is a bare
    /// identifier, as POV-Ray passes it) stand for the caller's variable: reading, #declare and
    /// #local of the parameter all reach it.
    Scopes scopes_;
    /// An identifier's number: the one it was read with, else its text's.
    uint32_t name_of(const Token& t) const {
        return t.name != Scopes::kNoName ? t.name : scopes_.find(t.text);
    }
    /// The same, given one if it has none yet (a name about to be declared).
    uint32_t intern_of(const Token& t) {
        return t.name != Scopes::kNoName ? t.name : scopes_.intern(t.text);
    }
    std::unordered_map<std::string, Macro> macros_;
    std::vector<bool> macro_named_;      // by name (Scopes): some #macro had this name
    std::map<std::string, bool> warned_; // de-duplication of identical warnings
    int macro_depth_ = 0;
    std::map<std::string, std::shared_ptr<const TokenFile>> file_cache_;
    std::map<std::string, std::shared_ptr<const PovDensity>> densities_; // density files read
    void pop_frame();
    void skip_raw_to_end(int levels, const Token& from);
    void switch_scan(const Token& from);
    void end_directive(const Token& where);
    void break_directive(const Token& where);
    std::shared_ptr<const TokenFile> load_tokens(const std::string& path, const Token* where);
};

} // namespace sheaf::io::pov
