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

// Studio's headings: ('NAME', 'Category'), before 1.1 ('NAME', None); the scalars after one are
// its own. Added, renamed and deleted as the others are.
TEST(LpyScalars, CategoriesAreHeadings) {
    std::string error;
    std::string t = addLpyScalar(kModel, scalar("Growth", LpyScalar::Kind::Category, 0, 0, 0), error);
    EXPECT_NE(t.find("('H', 'Integer', 3, 1, 20), ('Growth', 'Category')]"), std::string::npos) << t;
    t = addLpyScalar(t, scalar("rate", LpyScalar::Kind::Float, 0.5, 0, 1), error);
    auto all = lpyScalars(t);
    ASSERT_EQ(all.size(), 4u);
    EXPECT_EQ(all[2].kind, LpyScalar::Kind::Category);
    EXPECT_EQ(all[3].name, "rate");
    t = renameLpyScalar(t, "Growth", "Shape", error);
    EXPECT_NE(t.find("('Shape', 'Category'), ('rate'"), std::string::npos) << t;
    t = removeLpyScalar(t, "Shape", error);
    EXPECT_NE(t.find("('H', 'Integer', 3, 1, 20), ('rate', 'Float', 0.5, 0.0, 1.0, 2)]"), std::string::npos) << t;
    const std::string old = "def __initialiseContext__(context):\n\tscalars = [('Looks', None), ('w', 0.5, 0, 1)]\n";
    all = lpyScalars(old);
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[0].kind, LpyScalar::Kind::Category) << "L-Py 1.0's heading";
    EXPECT_EQ(all[1].kind, LpyScalar::Kind::Float);
    t = addLpyScalar(old, scalar("More", LpyScalar::Kind::Category, 0, 0, 0), error);
    EXPECT_NE(t.find("('w', 0.5, 0, 1), ('More', None)]"), std::string::npos) << "the list's own form: " << t;
}

}  // namespace
}  // namespace sprout
