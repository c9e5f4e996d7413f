// Files: #include with its search path, and #fopen/#read/#write/#fclose. Reads are allowed
// only under the scene's folder, writes only under the current folder.
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace sheaf::io::pov {

namespace {

bool is_under(const fs::path& p, const fs::path& dir) {
    std::error_code ea, eb; // a name the system refuses (too long ...) is under nothing
    const fs::path a = fs::weakly_canonical(p, ea), b = fs::weakly_canonical(dir, eb);
    if (ea || eb) return false;
    auto ai = a.begin();
    for (auto bi = b.begin(); bi != b.end(); ++bi, ++ai) {
        if (bi->empty()) continue;
        if (ai == a.end() || *ai != *bi) return false;
    }
    return true;
}

std::string format_number(double d) {
    char buf[64];
    if (d == std::floor(d) && std::fabs(d) < 1e15)
        std::snprintf(buf, sizeof buf, "%.0f", d);
    else
        std::snprintf(buf, sizeof buf, "%.6g", d);
    return buf;
}

} // namespace

std::string Parser::find_include(const std::string& name, const Token& where) const {
    return find_file(name, where, "include file");
}

std::string Parser::find_file(const std::string& name, const Token& where, const std::string& what,
                              const std::vector<std::string>& extensions) const {
    // The system would read the name only up to the NUL, and so find another file.
    if (name.find('\0') != std::string::npos)
        error_at(where, "the " + what + "'s name contains a NUL character");
    std::vector<fs::path> dirs;
    auto add = [&](const fs::path& d) { // each folder once, in the order first named
        if (std::find(dirs.begin(), dirs.end(), d.lexically_normal()) == dirs.end())
            dirs.push_back(d.lexically_normal());
    };
    add(fs::path(file_names_[where.file]).parent_path());
    for (const std::string& d : options_.include_paths) add(d);
    std::error_code ec; // a name the system refuses (too long ...) is not found
    if (fs::is_directory("/usr/share/povray-3.7/include", ec)) add("/usr/share/povray-3.7/include");
    // A name without an extension may leave it out (POV-Ray's image_map { "sign" }).
    std::vector<std::string> names{name};
    if (fs::path(name).extension().empty())
        for (const std::string& e : extensions) names.push_back(name + e);
    for (const std::string& n : names) {
        if (fs::path(n).is_absolute()) {
            if (fs::is_regular_file(n, ec)) return n;
            continue;
        }
        for (const fs::path& d : dirs) {
            const fs::path p = d / n;
            if (fs::is_regular_file(p, ec)) return p.lexically_normal().string();
        }
    }
    std::string searched;
    for (const fs::path& d : dirs) searched += (searched.empty() ? "" : ", ") + d.string();
    error_at(where, "cannot find " + what + " '" + name + "' (searched " + searched + ")");
}

void Parser::include_directive(const Token& where) {
    const Token& at = peek();
    const Value v = parse_condition(); // the including file stays open while it is read
    if (v.type != VType::String) error_expected(at, "the include file's name");
    const std::string name = v.str;
    const std::string path = find_include(name, where);
    int depth = 0;
    std::error_code ec;
    const fs::path canon = fs::weakly_canonical(path, ec);
    for (const Frame& f : frames_) {
        if (f.macro) continue;
        ++depth;
        if (!canon.empty() && fs::weakly_canonical(f.file->path, ec) == canon)
            error_at(where, "'" + name + "' includes itself");
    }
    if (depth > kMaxIncludeDepth)
        error_at(where, "includes nested deeper than " + std::to_string(kMaxIncludeDepth));
    push_file(path, where);
}

void Parser::fopen_directive(const Token& where) {
    const std::string id = expect_ident("a file identifier");
    const std::string name = parse_string();
    const Token mode = next();
    PovFileHandle h;
    if (is_kw_tok(mode, "read")) {
        fs::path p = name;
        if (p.is_relative()) p = fs::path(scene_dir_) / p;
        if (!is_under(p, scene_dir_))
            error_at(where, "#fopen may read only under the scene's folder, not '" + name + "'");
        h.reading = true;
        h.tokens = load_tokens(p.lexically_normal().string(), &where);
    } else if (is_kw_tok(mode, "write") || is_kw_tok(mode, "append")) {
        std::error_code ea, ec;
        const fs::path target = fs::absolute(name, ea), here = fs::current_path(ec);
        if (ea || ec || !is_under(target, here))
            error_at(where, "#fopen may write only under the current folder, not '" + name + "'");
        h.out = std::make_shared<std::ofstream>(name, is_kw_tok(mode, "append") ? std::ios::app
                                                                                : std::ios::trunc);
        if (!*h.out) error_at(where, "cannot write '" + name + "'");
    } else {
        error_expected(mode, "read, write or append");
    }
    declare(id, Value::boxed(VType::File, std::move(h)), false);
}

void Parser::read_directive(const Token& where) {
    expect_sym("(");
    const std::string id = expect_ident("a file identifier");
    Value* fv = lookup_mut(id);
    if (!fv || fv->type != VType::File || !fv->as<PovFileHandle>().reading)
        error_at(where, "'" + id + "' is not a file open for reading");
    PovFileHandle& h = fv->as<PovFileHandle>();
    const auto& toks = h.tokens->tokens;
    while (accept_sym(",")) {
        const std::string var = expect_ident("a variable to read into");
        auto number = [&](double& out) {
            double sign = 1;
            while (toks[h.pos].kind == TokKind::Symbol &&
                   (toks[h.pos].text == "-" || toks[h.pos].text == "+"))
                sign *= toks[h.pos++].text == "-" ? -1 : 1;
            if (toks[h.pos].kind != TokKind::Number)
                error_expected(toks[h.pos], "a number in the data file");
            out = sign * toks[h.pos++].number;
        };
        const Token& t = toks[h.pos];
        if (t.kind == TokKind::End) break;
        Value v;
        if (t.kind == TokKind::String) {
            v = Value::string(t.text);
            ++h.pos;
        } else if (t.kind == TokKind::Symbol && t.text == "<") {
            ++h.pos;
            double c[5];
            int n = 0;
            for (;;) {
                if (n == 5) error_expected(toks[h.pos], "'>'");
                number(c[n++]);
                if (toks[h.pos].kind == TokKind::Symbol && toks[h.pos].text == ",")
                    ++h.pos;
                else
                    break;
            }
            if (!(toks[h.pos].kind == TokKind::Symbol && toks[h.pos].text == ">"))
                error_expected(toks[h.pos], "'>'");
            ++h.pos;
            v = Value::vec(n, c);
        } else {
            double d;
            number(d);
            v = Value::number(d);
        }
        if (toks[h.pos].kind == TokKind::Symbol && toks[h.pos].text == ",") ++h.pos;
        declare(var, std::move(v), false);
    }
    expect_sym(")");
    if (toks[h.pos].kind == TokKind::End) // all read: the file closes, defined(id) is false
        scopes_.erase_everywhere(scopes_.find(id));
}

void Parser::write_directive(const Token& where) {
    expect_sym("(");
    const std::string id = expect_ident("a file identifier");
    const Value* fv = lookup(id);
    if (!fv || fv->type != VType::File || !fv->as<PovFileHandle>().out)
        error_at(where, "'" + id + "' is not a file open for writing");
    std::ofstream& out = *fv->as<PovFileHandle>().out;
    for (;;) {
        accept_sym(",");
        if (is_sym_tok(peek(), ")")) break;
        const Value v = parse_expr();
        if (v.type == VType::String) {
            out << v.str;
        } else if (v.type == VType::Float) {
            out << format_number(v.v[0]);
        } else if (v.numeric()) {
            out << "<";
            for (int i = 0; i < v.dim; ++i) out << (i ? "," : "") << format_number(v.v[i]);
            out << ">";
        } else {
            error_at(where, "#write takes strings, floats and vectors");
        }
    }
    expect_sym(")");
}

} // namespace sheaf::io::pov
