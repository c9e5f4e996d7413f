// The POV-Ray tokenizer: splits a scene file into identifiers, numbers, strings and symbols,
// each with its file, line and column. Comments (// and nested /* */) are dropped.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace sheaf::io::pov {

enum class TokKind { Ident, Number, String, Symbol, End };

struct Token {
    TokKind kind = TokKind::End;
    std::string text; // identifier, symbol, the string's value, or the number as written
    double number = 0;
    int file = 0; // index into the reader's file names
    int line = 1, col = 1;
    uint32_t name = 0xFFFFFFFFu; // an identifier's number in the reader's Scopes, once read
};

/// A whole file's tokens; the last one is always TokKind::End.
struct TokenFile {
    std::string path;
    int file = 0;
    std::vector<Token> tokens;
};

/// Tokenizes `text`. `name` is used in error messages (SceneError "NAME:LINE:COL: error: ...").
std::shared_ptr<TokenFile> tokenize(const std::string& text, const std::string& name, int file);

/// How a token appears in messages: its text, or "end of file".
std::string describe(const Token& t);

} // namespace sheaf::io::pov
