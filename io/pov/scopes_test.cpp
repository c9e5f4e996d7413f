// The reader's scopes: innermost wins, references reach the caller's variable, #undef and
// the end of a macro uncover what was shadowed, and a value keeps its address.
#include "io/pov/scopes.h"

#include <gtest/gtest.h>

namespace sheaf::io::pov {
namespace {

double num(const Value* v) {
    return v ? v->v[0] : -1;
}

TEST(Scopes, InnermostWinsAndPopUncovers) {
    Scopes s;
    const uint32_t a = s.intern("A"), b = s.intern("B");
    EXPECT_EQ(s.intern("A"), a);
    EXPECT_EQ(s.find("A"), a);
    EXPECT_EQ(s.find("never"), Scopes::kNoName);
    EXPECT_EQ(s.lookup(s.find("never")), nullptr);
    EXPECT_EQ(s.text(b), "B");
    s.set(0, a, Value::number(1));
    Value* outer = s.lookup(a);
    s.push({{a, Value::number(2)}}, {});
    EXPECT_EQ(num(s.lookup(a)), 2);
    s.push();
    s.set(2, a, Value::number(3)); // a #local in an include inside the macro
    s.set(0, b, Value::number(4)); // a #declare of a new name goes to the scene's scope
    EXPECT_EQ(num(s.lookup(a)), 3);
    s.pop();
    EXPECT_EQ(num(s.lookup(a)), 2);
    s.pop();
    EXPECT_EQ(s.lookup(a), outer); // the address held through the calls
    EXPECT_EQ(num(outer), 1);
    EXPECT_EQ(num(s.lookup(b)), 4);
}

TEST(Scopes, ReferencesReachTheCallersVariable) {
    Scopes s;
    const uint32_t v = s.intern("V"), p = s.intern("P"), q = s.intern("Q");
    s.push();
    s.set(1, v, Value::number(1)); // the caller's #local V
    Scopes::Ref where;
    ASSERT_TRUE(s.find_variable(v, 1, where));
    EXPECT_EQ(where.scope, 1u);
    EXPECT_FALSE(s.find_variable(v, 0, where)); // not seen from the scene's scope
    // Macro(P, Q) called as Macro(V, 5): P stands for V, Q holds 5 (a value given for a
    // referenced name is dropped).
    s.push({{p, Value::number(9)}, {q, Value::number(5)}}, {{p, where}});
    EXPECT_EQ(num(s.lookup(p)), 1);
    s.set(2, p, Value::number(7)); // #local P = 7 assigns V
    EXPECT_EQ(num(s.lookup(q)), 5);
    Scopes::Ref again;
    ASSERT_TRUE(s.find_variable(p, 2, again)); // a nested call passing P on reaches V
    EXPECT_EQ(again.scope, 1u);
    EXPECT_EQ(again.name, v);
    s.pop();
    EXPECT_EQ(num(s.lookup(v)), 7);
    EXPECT_EQ(s.lookup(p), nullptr);
    // A reference whose variable was removed reads as undeclared.
    s.push({}, {{p, where}});
    EXPECT_TRUE(s.erase_innermost(v));
    EXPECT_EQ(s.lookup(p), nullptr);
    EXPECT_FALSE(s.find_variable(p, 2, again));
    s.set(2, p, Value::number(8)); // assigning through it makes the variable again
    EXPECT_EQ(num(s.lookup(v)), 8);
    s.pop();
    s.pop();
    EXPECT_EQ(s.lookup(v), nullptr);
}

TEST(Scopes, UndefRemovesTheInnermostVariable) {
    Scopes s;
    const uint32_t a = s.intern("A");
    s.set(0, a, Value::number(1));
    s.push();
    s.set(1, a, Value::number(2));
    EXPECT_TRUE(s.erase_innermost(a));
    EXPECT_EQ(num(s.lookup(a)), 1);
    s.set(1, a, Value::number(3));
    s.erase_everywhere(a);
    EXPECT_EQ(s.lookup(a), nullptr);
    EXPECT_FALSE(s.erase_innermost(a));
    s.set(1, a, Value::number(4)); // erased and made again: the scope's end removes it once
    s.pop();
    EXPECT_EQ(s.lookup(a), nullptr);
}

} // namespace
} // namespace sheaf::io::pov
