// A model file in any encoding L-Py reads (issue 51): its bytes decoded as L-Py's Python
// decodes them (lpy/translate/encoding.cpp), so a Latin-1 model opens; and a step that grows a
// few modules into many (an Init that makes its whole string) is no rate for the next one.
#include <gtest/gtest.h>

#include <string>

#include "lpy/lpy.hpp"
#include "lpy/translate/translate.hpp"
#include "tests/lpy/lpy_messages.hpp"

namespace sprout {
namespace {

TEST(LpyEncoding, BytesAreDecodedAsLpysPythonDecodesThem) {
    // UTF-8 stays as it is (a byte order mark dropped).
    EXPECT_EQ(lpy::modelTextAsUtf8("x = 'caf\xC3\xA9'\n"), "x = 'caf\xC3\xA9'\n");
    EXPECT_EQ(lpy::modelTextAsUtf8("\xEF\xBB\xBFx = 1\n"), "x = 1\n");
    // A byte that is not UTF-8 is the Latin-1 character it is; UTF-8 beside it stays.
    EXPECT_EQ(lpy::modelTextAsUtf8("# r\xE8gle\nx = '\xC3\xA9'\n"), "# r\xC3\xA8gle\nx = '\xC3\xA9'\n");
    // Overlong forms and surrogates are not UTF-8 (Python refuses them): byte by byte.
    EXPECT_EQ(lpy::modelTextAsUtf8("\xC0\xAF"), "\xC3\x80\xC2\xAF");
    EXPECT_EQ(lpy::modelTextAsUtf8("\xED\xA0\x80"), "\xC3\xAD\xC2\xA0\xC2\x80");
    // A coding cookie on the first or second line decodes the whole file with it.
    EXPECT_EQ(lpy::modelTextAsUtf8("# -*- coding: latin-1 -*-\nx = '\xE9'\n"), "# -*- coding: latin-1 -*-\nx = '\xC3\xA9'\n");
    EXPECT_EQ(lpy::modelTextAsUtf8("#!/usr/bin/env python\n# vim: set fileencoding=iso-8859-1 :\n'\xC3\xA9'"),
              "#!/usr/bin/env python\n# vim: set fileencoding=iso-8859-1 :\n'\xC3\x83\xC2\xA9'");
    EXPECT_EQ(lpy::modelTextAsUtf8("# coding: cp1252\n'\x80\x93'"), "# coding: cp1252\n'\xE2\x82\xAC\xE2\x80\x9C'");
    // A cookie after a line of code is none.
    EXPECT_EQ(lpy::modelTextAsUtf8("x = 1\n# coding: latin-1\n'\xC3\xA9'"), "x = 1\n# coding: latin-1\n'\xC3\xA9'");
}

TEST(LpyEncoding, ALatin1ModelDerives) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    // Written in Latin-1: accents in comments, in the Python header and in a rule's line.
    const std::string text =
        "# Mod\xE8le \xE9" "crit en Latin-1 : une tige\n"
        "longueur = 2.5  # \xE9paisseur\n"
        "Axiom: A(1)\n"
        "derivation length: 3\n"
        "production:\n"
        "# r\xE8gle de croissance\n"
        "A(x) --> F(x * longueur) A(x + 1)  # d\xE9j\xE0\n"
        "endlsystem\n";
    lpy::Model m = lpy::runModel(text, {});
    ASSERT_TRUE(m.ok()) << messages(m);
    EXPECT_EQ(m.derived, "F(2.5)F(5.0)F(7.5)A(4)");
    // With a cookie, a Latin-1 string literal reads as L-Py reads it.
    lpy::Model named = lpy::runModel("# -*- coding: latin-1 -*-\nnom = 'caf\xE9'\nAxiom: A(len(nom), nom == 'caf\\u00e9')\nproduction:\nendlsystem\n", {});
    ASSERT_TRUE(named.ok()) << messages(named);
    EXPECT_EQ(named.derived, "A(4,True)");
}

TEST(LpyGrowth, AStepFromAFewModulesIsNoRateOfGrowth) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    // Init makes 20,000 modules from one (L-Py's lsystem5.lpy makes its axiom from an MTG so);
    // the next steps grow by two: derived, not refused as 20,000 times 20,000.
    const std::string text =
        "Axiom: Init\nderivation length: 3\nproduction:\n"
        "Init:\n    nsproduce(Lstring('A' * 20000))\n"
        "A --> B\n"
        "endlsystem\n";
    lpy::Model m = lpy::runModel(text, {});
    ASSERT_TRUE(m.ok()) << messages(m);
    EXPECT_EQ(m.stepsDone, 3);
    EXPECT_EQ(m.derived, std::string(20000, 'B'));
}

}  // namespace
}  // namespace sprout
