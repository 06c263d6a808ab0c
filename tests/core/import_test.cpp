// Importers: Lparser .ls and Fractint .l translated to .lsys.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/language/file_kind.hpp"
#include "core/language/import/import.hpp"
#include "core/turtle/turtle.hpp"
#include "test_util.hpp"

namespace sprout::test {
namespace {

std::string lineOf(const std::string& text, const std::string& prefix) {
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);)
        if (l.rfind(prefix, 0) == 0) return l;
    return "<none>";
}

TEST(Lparser, CommandsAreMappedToSproutsTurtle) {
    ImportResult r = importLparser(
        "# comment\nrecursion 3\nangle 30\nthickness 20\nmin_thickness 1\nshape 1\nswitch_yz 1\n"
        "axiom c(12)F>(20)<%|$_Zz\"'(.8);:?!(.75)t(.3)~G\nrule F = F[+F]g.{}   # trailing comment\n",
        "t.ls");
    ASSERT_TRUE(r.ok()) << r.diagnostics[0].message;
    EXPECT_EQ(lineOf(r.text, "n:"), "n: 3");
    EXPECT_EQ(lineOf(r.text, "angle:"), "angle: 30");
    EXPECT_EQ(lineOf(r.text, "width:"), "width: 0.2");
    EXPECT_EQ(lineOf(r.text, "axiom:"),
              "axiom: ;(12)F\\(20)//(180)|$@L(0.5)F@L(2)@L(0.5)f@L(2)@L(1.1)@L(.8)@A(1.1)@A(0.9)@W(1.4)@W(.75)@T(.3)"
              "+(rand(-(30.000000),(30.000000)))&(rand(-(30.000000),(30.000000)))/(rand(-(30.000000),(30.000000)))LpG");
    EXPECT_EQ(lineOf(r.text, "F ->"), "F -> F[+F]g.{}");
    EXPECT_EQ(lineOf(r.text, "module:"), "module: LpG");  // G would draw in Sprout: renamed
    auto g = grammarOf(r.text);
    ASSERT_TRUE(g);
}

TEST(Lparser, PositionalFormat) {
    ImportResult r = importLparser("4\n25\n30\nF\nF=F[+F]F\n@\n", "old.ls");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(lineOf(r.text, "n:"), "n: 4");
    EXPECT_EQ(lineOf(r.text, "angle:"), "angle: 25");
    EXPECT_EQ(expand(r.text, 1), "F[+F]F");
}

TEST(Lparser, ColoursAndErrors) {
    ImportResult r = importLparser("color 2 255 0 16\naxiom c(2)F\n", "c.ls");
    ASSERT_TRUE(r.ok());
    EXPECT_NE(lineOf(r.text, "palette:").find("#ff0010"), std::string::npos);
    ImportResult bad = importLparser("recursion x\nfrobnicate 3\nrule AB = F\n", "bad.ls");
    ASSERT_EQ(bad.diagnostics.size(), 4u);
    EXPECT_EQ(bad.diagnostics[0].line, 1);
    EXPECT_EQ(bad.diagnostics[1].message, "unknown Lparser keyword 'frobnicate' (ignored)");
    EXPECT_EQ(bad.diagnostics[1].severity, Severity::Warning);
    EXPECT_EQ(bad.diagnostics[2].message, "expected 'rule X = successor' with a one-character X");
    EXPECT_EQ(bad.diagnostics[3].message, "the file has no axiom");
}

TEST(Fractint, SystemsAndConventions) {
    const char* file =
        "Dragon { ; a comment\n  Angle 8\n  Axiom FX\n  F=\n  y=+FX--FY+\n  x=-FX++FY-\n  }\n"
        "Odd {\n angle=6;\n axiom F\\45F/30F!F|@I2F@Q4F<2F\n F=FF\n F=+\n }\n";
    auto systems = listFractint(file);
    ASSERT_EQ(systems.size(), 2u);
    EXPECT_EQ(systems[1].name, "Odd");
    ImportResult d = importFractint(file, "dragon");  // names are case-insensitive
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(lineOf(d.text, "angle:"), "angle: 45");
    EXPECT_EQ(lineOf(d.text, "Y ->"), "Y -> +FX--FY+");
    EXPECT_EQ(expand(d.text, 1), "-FX++FY-");  // F= deletes F
    EXPECT_EQ(expand(d.text, 2), "--FX++FY-+++FX--FY+-");
    ImportResult o = importFractint(file, "Odd");
    ASSERT_TRUE(o.ok());
    EXPECT_EQ(lineOf(o.text, "angle:"), "angle: 60");
    EXPECT_EQ(lineOf(o.text, "axiom:"), "axiom: F+(45)F-(30)F@A(-1)F|@L(1/2)F@L(sqrt(4))F;;F");
    EXPECT_EQ(lineOf(o.text, "F ->"), "F -> FF+");  // several rules for a letter are joined
    EXPECT_FALSE(importFractint(file, "Nope").ok());
}

TEST(Fractint, BangSwapsTheTurns) {
    auto g = grammarOf("angle: 90\nwidth: 0.1\naxiom: F+F@A(-1)F+F\n");
    Geometry geo;
    interpret(g->axiom, *g, {}, geo);
    ASSERT_EQ(geo.cylinders.size(), 4u);
    EXPECT_NEAR(geo.cylinders[2].end.x, -2, 1e-5);  // after '!', + turns the other way
    EXPECT_NEAR(geo.cylinders[3].end.y, 2, 1e-5);
}

// The real collections, when ../shared is there: every file loads, derives and draws.
const std::filesystem::path kCorpus = std::filesystem::path(SPROUT_SHARED_DIR) / "corpus";

std::string readAll(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void expectDraws(const std::string& text, const std::string& what) {
    ParseResult r = parse(text);
    for (const auto& d : r.diagnostics) ADD_FAILURE() << what << ": " << formatDiagnostic(d, "<converted>") << "\n" << text;
    ASSERT_TRUE(r.ok()) << what;
    DeriveResult d = derive(r.grammar, r.grammar->settings.iterations);
    ASSERT_TRUE(d.outcome.ok()) << what << ": " << d.outcome.message;
    Geometry geo;
    interpret(*d.string, *r.grammar, {r.grammar->settings.iterations, 1, nullptr}, geo);
    EXPECT_GT(geo.cylinders.size() + geo.polygons.indices.size(), 0u) << what;
}

TEST(Corpus, EveryLparserFileLoadsAndDraws) {
    if (!std::filesystem::exists(kCorpus / "lparser")) GTEST_SKIP() << "no shared corpus here";
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(kCorpus / "lparser")) {
        if (e.path().extension() != ".ls") continue;
        ++files;
        // Told from L-system Explorer's `.ls` files by its content.
        EXPECT_EQ(detectFileKind(e.path().string(), readAll(e.path())), FileKind::Lparser) << e.path();
        ImportResult r = importLparser(readAll(e.path()), e.path().filename().string());
        for (const auto& d : r.diagnostics) ADD_FAILURE() << formatDiagnostic(d, e.path().string());
        expectDraws(r.text, e.path().filename().string());
    }
    EXPECT_EQ(files, 30);
}

TEST(Corpus, EveryFractintSystemLoadsAndDraws) {
    if (!std::filesystem::exists(kCorpus / "fractint.l")) GTEST_SKIP() << "no shared corpus here";
    std::string text = readAll(kCorpus / "fractint.l");
    auto systems = listFractint(text);
    EXPECT_EQ(systems.size(), 69u);
    for (const auto& s : systems) {
        ImportResult r = importFractint(text, s.name);
        for (const auto& d : r.diagnostics) ADD_FAILURE() << formatDiagnostic(d, "fractint.l (" + s.name + ")");
        expectDraws(r.text, s.name);
    }
}


// The six Lparser listings of seed document 001, as printed (with the typos and lost
// characters of the text: `switch_ yz`, `".7)`, a missing ']', wrapped lines).
TEST(Lparser, TheSeedDocumentsListingsLoadAsPrinted) {
    const std::filesystem::path dir = std::filesystem::path(SPROUT_TEST_DATA) / "seed001";
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        ++files;
        // Told from L-system Explorer's `.ls` files by its content.
        EXPECT_EQ(detectFileKind(e.path().string(), readAll(e.path())), FileKind::Lparser) << e.path();
        ImportResult r = importLparser(readAll(e.path()), e.path().filename().string());
        EXPECT_TRUE(r.ok()) << e.path();
        for (const auto& d : r.diagnostics)
            EXPECT_EQ(d.severity, Severity::Warning) << formatDiagnostic(d, e.path().string());
        expectDraws(r.text, e.path().filename().string());
    }
    EXPECT_EQ(files, 6);
}

}  // namespace
}  // namespace sprout::test
