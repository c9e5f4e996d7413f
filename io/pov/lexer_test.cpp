// Tests of the POV-Ray tokenizer: kinds, positions, comments, strings and numbers.
#include "io/pov/lexer.h"

#include "core/base/error.h"

#include <gtest/gtest.h>

namespace sheaf::io::pov {
namespace {

TEST(PovLexer, KindsAndPositions) {
    const auto f = tokenize("sphere {\n  <0, 1.5>, .25e1 // comment\n}", "a.pov", 0);
    ASSERT_EQ(f->tokens.size(), 11u); // sphere { < 0 , 1.5 > , 2.5 } end
    EXPECT_EQ(f->tokens[0].kind, TokKind::Ident);
    EXPECT_EQ(f->tokens[0].text, "sphere");
    EXPECT_EQ(f->tokens[1].text, "{");
    EXPECT_EQ(f->tokens[1].col, 8);
    EXPECT_EQ(f->tokens[2].text, "<");
    EXPECT_EQ(f->tokens[2].line, 2);
    EXPECT_EQ(f->tokens[2].col, 3);
    EXPECT_EQ(f->tokens[5].kind, TokKind::Number);
    EXPECT_DOUBLE_EQ(f->tokens[5].number, 1.5);
    EXPECT_DOUBLE_EQ(f->tokens[8].number, 2.5);
    EXPECT_EQ(f->tokens[8].col, 13);
    EXPECT_EQ(f->tokens[9].text, "}");
    EXPECT_EQ(f->tokens[9].line, 3);
    EXPECT_EQ(f->tokens[10].kind, TokKind::End);
}

TEST(PovLexer, NestedBlockComments) {
    const auto f = tokenize("a /* x /* nested */ still comment */ b", "a.pov", 0);
    ASSERT_EQ(f->tokens.size(), 3u);
    EXPECT_EQ(f->tokens[1].text, "b");
    EXPECT_EQ(f->tokens[1].col, 38);
}

TEST(PovLexer, StringsWithEscapes) {
    const auto f = tokenize(R"("a\"b\\c\n")", "a.pov", 0);
    ASSERT_EQ(f->tokens[0].kind, TokKind::String);
    EXPECT_EQ(f->tokens[0].text, "a\"b\\c\n");
}

TEST(PovLexer, TwoCharacterSymbolsAndMembers) {
    const auto f = tokenize("a<=b != c >= V.x 1.x", "a.pov", 0);
    std::vector<std::string> t;
    for (const Token& k : f->tokens) t.push_back(k.text);
    EXPECT_EQ(t, (std::vector<std::string>{"a", "<=", "b", "!=", "c", ">=", "V", ".", "x", "1", ".",
                                           "x", ""}));
}

TEST(PovLexer, ErrorsHavePositions) {
    try {
        tokenize("a\n  \"open", "s.pov", 0);
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "s.pov:2:3: error: unterminated string");
    }
    EXPECT_THROW(tokenize("/* never closed", "s.pov", 0), SceneError);
    EXPECT_THROW(tokenize("a ` b", "s.pov", 0), SceneError);
}

} // namespace
} // namespace sheaf::io::pov
