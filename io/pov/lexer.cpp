// The POV-Ray tokenizer (see lexer.h).
#include "io/pov/lexer.h"

#include "core/base/error.h"

#include <cctype>
#include <cstdlib>

namespace sheaf::io::pov {

namespace {

struct Cursor {
    const std::string& s;
    const std::string& name;
    size_t i = 0;
    int line = 1, col = 1;

    char at(size_t k = 0) const { return i + k < s.size() ? s[i + k] : '\0'; }
    void step() {
        if (s[i] == '\n') {
            ++line, col = 1;
        } else {
            ++col;
        }
        ++i;
    }
    [[noreturn]] void fail(int l, int c, const std::string& msg) const {
        throw SceneError(name + ":" + std::to_string(l) + ":" + std::to_string(c) +
                         ": error: " + msg);
    }
};

bool ident_start(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool ident_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
bool digit(char c) {
    return c >= '0' && c <= '9';
}

void skip_block_comment(Cursor& c) {
    const int l = c.line, col = c.col;
    c.step(), c.step();
    int depth = 1;
    while (depth > 0) {
        if (c.i >= c.s.size()) c.fail(l, col, "unterminated comment");
        if (c.at() == '/' && c.at(1) == '*') {
            c.step(), c.step(), ++depth;
        } else if (c.at() == '*' && c.at(1) == '/') {
            c.step(), c.step(), --depth;
        } else {
            c.step();
        }
    }
}

std::string read_string(Cursor& c) {
    const int l = c.line, col = c.col;
    c.step();
    std::string out;
    for (;;) {
        if (c.i >= c.s.size() || c.at() == '\n') c.fail(l, col, "unterminated string");
        const char ch = c.at();
        if (ch == '"') {
            c.step();
            return out;
        }
        if (ch == '\\') {
            const char e = c.at(1);
            c.step();
            switch (e) {
            case 'n':
                out += '\n';
                break;
            case 't':
                out += '\t';
                break;
            case 'r':
                out += '\r';
                break;
            case 'a':
                out += '\a';
                break;
            case 'b':
                out += '\b';
                break;
            case 'f':
                out += '\f';
                break;
            case 'v':
                out += '\v';
                break;
            case '\\':
                out += '\\';
                break;
            case '"':
                out += '"';
                break;
            case '\'':
                out += '\'';
                break;
            default:
                out += '\\';
                continue; // kept as written (POV-Ray warns)
            }
            c.step();
            continue;
        }
        out += ch;
        c.step();
    }
}

} // namespace

std::shared_ptr<TokenFile> tokenize(const std::string& text, const std::string& name, int file) {
    auto out = std::make_shared<TokenFile>();
    out->path = name;
    out->file = file;
    Cursor c{text, name};
    for (;;) {
        const char ch = c.at();
        if (c.i >= text.size()) break;
        if (std::isspace(static_cast<unsigned char>(ch))) {
            c.step();
            continue;
        }
        if (ch == '/' && c.at(1) == '/') {
            while (c.i < text.size() && c.at() != '\n') c.step();
            continue;
        }
        if (ch == '/' && c.at(1) == '*') {
            skip_block_comment(c);
            continue;
        }
        Token t;
        t.file = file, t.line = c.line, t.col = c.col;
        if (ident_start(ch)) {
            const size_t b = c.i;
            while (ident_char(c.at())) c.step();
            t.kind = TokKind::Ident;
            t.text = text.substr(b, c.i - b);
        } else if (digit(ch) || (ch == '.' && digit(c.at(1)))) {
            const size_t b = c.i;
            while (digit(c.at())) c.step();
            if (c.at() == '.' && !ident_start(c.at(1))) {
                c.step();
                while (digit(c.at())) c.step();
            }
            if ((c.at() == 'e' || c.at() == 'E') &&
                (digit(c.at(1)) || ((c.at(1) == '+' || c.at(1) == '-') && digit(c.at(2))))) {
                c.step(), c.step();
                while (digit(c.at())) c.step();
            }
            t.kind = TokKind::Number;
            t.text = text.substr(b, c.i - b);
            t.number = std::strtod(t.text.c_str(), nullptr);
        } else if (ch == '"') {
            t.kind = TokKind::String;
            t.text = read_string(c);
        } else {
            static const char* two[] = {"<=", ">=", "!="};
            t.kind = TokKind::Symbol;
            for (const char* p : two)
                if (ch == p[0] && c.at(1) == p[1]) t.text = p;
            if (t.text.empty()) {
                if (std::string("{}()[]<>,;.+-*/?:=!&|#").find(ch) == std::string::npos)
                    c.fail(c.line, c.col, std::string("unexpected character '") + ch + "'");
                t.text = std::string(1, ch);
            }
            for (size_t k = 0; k < t.text.size(); ++k) c.step();
        }
        out->tokens.push_back(std::move(t));
    }
    Token end;
    end.file = file, end.line = c.line, end.col = c.col;
    out->tokens.push_back(end);
    return out;
}

std::string describe(const Token& t) {
    if (t.kind == TokKind::End) return "end of file";
    if (t.kind == TokKind::String) return "\"" + t.text + "\"";
    return t.text;
}

} // namespace sheaf::io::pov
