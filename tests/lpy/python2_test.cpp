// Files written for Python 2: the message says so at the line, with the Python 3 form
// (lpy/translate/python2_hints.hpp), where Python alone said "SyntaxError" or "NameError".
#include <gtest/gtest.h>

#include "lpy/lpy.hpp"
#include "lpy/translate/python2_hints.hpp"

namespace sprout {
namespace {

std::string said(std::string_view error, std::string_view line) {
    return lpy::python2Message(error, line).value_or("(none)");
}

TEST(LpyPython2, PrintAndExecStatementsAreWrittenAsCalls) {
    const char* print = "SyntaxError: Missing parentheses in call to 'print'. Did you mean print(...)?";
    EXPECT_EQ(said(print, "  print x"), "`print x` is Python 2: L-Py 3 does not read it either; write `print(x)`");
    EXPECT_EQ(said(print, "print 'step', n,   # no new line"),
              "`print 'step', n,` is Python 2: L-Py 3 does not read it either; write `print('step', n, end=' ')`");
    EXPECT_EQ(said(print, "print >>log, 'a', x"),
              "`print >>log, 'a', x` is Python 2: L-Py 3 does not read it either; write `print('a', x, file=log)`");
    EXPECT_EQ(said("SyntaxError: Missing parentheses in call to 'exec'. Did you mean exec(...)?", "exec code"),
              "`exec code` is Python 2: L-Py 3 does not read it either; write `exec(code)`");
}

TEST(LpyPython2, NamesAndMethodsGoneFromPython3) {
    EXPECT_EQ(said("NameError: name 'xrange' is not defined", "for i in xrange(10):"),
              "`xrange` is Python 2: L-Py 3 does not read it either; write `range`");
    EXPECT_EQ(said("AttributeError: 'dict' object has no attribute 'iteritems'", "for k, v in d.iteritems():"),
              "`.iteritems()` is Python 2: L-Py 3 does not read it either; write `.items()`");
    // A name of the model's own that is missing keeps Python's message.
    EXPECT_EQ(said("NameError: name 'grow' is not defined", "grow(x)"), "(none)");
}

TEST(LpyPython2, SyntaxOfPython2) {
    EXPECT_EQ(said("SyntaxError: multiple exception types must be parenthesized", "except ValueError, e:"),
              "`except ValueError, e:` is Python 2: L-Py 3 does not read it either; write `except ValueError as e:`");
    EXPECT_EQ(said("SyntaxError: invalid syntax", "raise ValueError, 'bad'"),
              "`raise ValueError, 'bad'` is Python 2: L-Py 3 does not read it either; write `raise ValueError('bad')`");
    EXPECT_EQ(said("SyntaxError: leading zeros in decimal integer literals are not permitted; use an 0o prefix for octal integers",
                   "mode = 0755"),
              "`0755` is Python 2: L-Py 3 does not read it either; write `0o755`");
    EXPECT_EQ(said("SyntaxError: invalid syntax", "if a <> b:"),
              "`if a <> b:` is Python 2: L-Py 3 does not read it either; write `if a != b:`");
    EXPECT_EQ(said("SyntaxError: invalid syntax", "s = `x`"),
              "backquotes around `x` are Python 2: L-Py 3 does not read them either; write `repr(x)`");
    // Python 3 syntax errors keep Python's message, even with '<>' or '`' inside a string.
    EXPECT_EQ(said("SyntaxError: expected ':'", "if True"), "(none)");
    EXPECT_EQ(said("SyntaxError: invalid syntax", "s = '<>' +"), "(none)");
}

TEST(LpyPython2, LinesAreReadWithTheirEnds) {
    EXPECT_EQ(lpy::lineOf("a\r\nb\nc", 1), "a");
    EXPECT_EQ(lpy::lineOf("a\r\nb\nc", 2), "b");
    EXPECT_EQ(lpy::lineOf("a\r\nb\nc", 3), "c");
    EXPECT_EQ(lpy::lineOf("a\nb", 4), "");
}

// A whole model, as `sprout render` runs it: the message at the line of the Python 2 code.
TEST(LpyPython2, AModelOfPython2SaysSoAtItsLine) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    lpy::RunOptions o;
    o.path = "old.lpy";
    lpy::Model p = lpy::runModel("Axiom: A\nderivation length: 1\nproduction:\nA :\n    print 'grows'\n    produce AB\nendlsystem\n", o);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.diagnostics.back().line, 5);
    EXPECT_EQ(p.diagnostics.back().message,
              "`print 'grows'` is Python 2: L-Py 3 does not read it either; write `print('grows')`");
    lpy::Model x = lpy::runModel("def Start():\n    for i in xrange(3): pass\nAxiom: A\nproduction:\nA --> AB\nendlsystem\n", o);
    ASSERT_FALSE(x.ok());
    EXPECT_EQ(x.diagnostics.back().line, 2);
    EXPECT_EQ(x.diagnostics.back().message, "`xrange` is Python 2: L-Py 3 does not read it either; write `range`");
}

}  // namespace
}  // namespace sprout
