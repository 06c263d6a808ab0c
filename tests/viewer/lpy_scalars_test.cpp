// An L-Py model's scalars created, renamed and deleted in its text (app/plant/lpy_scalars.hpp),
// as L-Py Studio's scalar editor writes them; lpyScalars reads every change back.
#include <gtest/gtest.h>

#include "app/plant/lpy_scalars.hpp"

namespace sprout {
namespace {

const std::string kModel =
    "Axiom: F(H)\nderivation length: 1\nproduction:\nendlsystem\n###### INITIALISATION ######\n\n__lpy_code_version__ = 1.1\n\n"
    "def __initialiseContext__(context):\n\tscalars = [('POINTS', 'Bool', True), ('H', 'Integer', 3, 1, 20)]\n"
    "\tcontext[\"__scalars__\"] = scalars\n\tfor s in scalars:\n\t\tif not s[1] == \"Category\" : context[s[0]] = s[2]\n";

LpyScalar scalar(const char* name, LpyScalar::Kind kind, double v, double lo, double hi) {
    LpyScalar s;
    s.name = name, s.kind = kind, s.value = v, s.min = lo, s.max = hi;
    return s;
}

TEST(LpyScalars, AddedToTheListAsStudioWritesThem) {
    std::string error;
    std::string t = addLpyScalar(kModel, scalar("angle", LpyScalar::Kind::Float, 0.5, 0, 1), error);
    EXPECT_NE(t.find("('H', 'Integer', 3, 1, 20), ('angle', 'Float', 0.5, 0.0, 1.0, 2)]"), std::string::npos) << t;
    const auto all = lpyScalars(t);
    ASSERT_EQ(all.size(), 3u);
    EXPECT_EQ(all[2].name, "angle");
    EXPECT_EQ(all[2].kind, LpyScalar::Kind::Float);
    EXPECT_EQ(all[2].max, 1);
    EXPECT_EQ(addLpyScalar(t, scalar("angle", LpyScalar::Kind::Float, 0, 0, 1), error), "");
    EXPECT_NE(error.find("already"), std::string::npos);
    EXPECT_EQ(addLpyScalar(t, scalar("2x", LpyScalar::Kind::Float, 0, 0, 1), error), "");
    EXPECT_EQ(addLpyScalar(t, scalar("for", LpyScalar::Kind::Float, 0, 0, 1), error), "") << "a keyword is no name";
}

TEST(LpyScalars, AModelWithoutScalarsGetsStudiosLines) {
    std::string error;
    const std::string bare = "Axiom: F(H)\nderivation length: 1\nproduction:\nendlsystem\n";
    const std::string t = addLpyScalar(bare, scalar("H", LpyScalar::Kind::Integer, 3, 1, 9), error);
    EXPECT_EQ(t, bare + "###### INITIALISATION ######\n\n__lpy_code_version__ = 1.1\n\ndef __initialiseContext__(context):\n"
                        "\tscalars = [('H', 'Integer', 3, 1, 9)]\n\tcontext[\"__scalars__\"] = scalars\n\tfor s in scalars:\n"
                        "\t\tif not s[1] == \"Category\" : context[s[0]] = s[2]\n");
    ASSERT_EQ(lpyScalars(t).size(), 1u);
    const std::string withContext = bare + "def __initialiseContext__(context):\n\tpass\n";
    const std::string u = addLpyScalar(withContext, scalar("on", LpyScalar::Kind::Bool, 1, 0, 1), error);
    EXPECT_NE(u.find("def __initialiseContext__(context):\n\tscalars = [('on', 'Bool', True)]\n"), std::string::npos) << u;
}

TEST(LpyScalars, RenamedAndDeleted) {
    std::string error;
    std::string t = renameLpyScalar(kModel, "H", "height", error);
    EXPECT_NE(t.find("('height', 'Integer', 3, 1, 20)"), std::string::npos);
    EXPECT_EQ(renameLpyScalar(t, "height", "POINTS", error), "") << "taken";
    EXPECT_EQ(renameLpyScalar(t, "nothing", "x", error), "");
    t = removeLpyScalar(t, "POINTS", error);
    EXPECT_NE(t.find("scalars = [('height', 'Integer', 3, 1, 20)]"), std::string::npos) << t;
    t = removeLpyScalar(t, "height", error);
    EXPECT_NE(t.find("scalars = []"), std::string::npos) << t;
    EXPECT_TRUE(lpyScalars(t).empty());
    t = addLpyScalar(t, scalar("k", LpyScalar::Kind::Integer, 2, 0, 4), error);
    EXPECT_NE(t.find("scalars = [('k', 'Integer', 2, 0, 4)]"), std::string::npos) << t;
    std::string last = removeLpyScalar(kModel, "H", error);  // the last: with the comma before it
    EXPECT_NE(last.find("scalars = [('POINTS', 'Bool', True)]"), std::string::npos) << last;
}

}  // namespace
}  // namespace sprout
