// Grammars as people write them (issue 22). tests/notation holds pairs written for Sprout:
// NAME.txt in ABOP's printed notation, a web tool's dialect or text as pasted from a PDF, and
// NAME.lsys, the same grammar in Sprout's own notation. Each .txt must be read as ABOP
// notation and derive exactly what its .lsys derives, at every step; it may carry
//   # expect N: STRING     step N as `sprout expand` prints it
//   # warning L: MESSAGE   a warning on line L (every warning but the pasted characters' listed)
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

#include "core/derive/derive.hpp"
#include "core/language/file_kind.hpp"
#include "tests/core/test_util.hpp"

namespace sprout {
namespace {

namespace fs = std::filesystem;

using test::slurp;

ParseResult parseFile(const fs::path& path, const std::string& text) {
    const FileKind kind = detectFileKind(path.string(), text);
    EXPECT_EQ(kind, FileKind::Lsys);
    return parse(text, parseOptionsFor(kind, path.string()));
}

std::vector<std::string> steps(const std::shared_ptr<const Grammar>& g) {
    std::vector<std::string> out;
    for (int n = 0; n <= g->settings.iterations; ++n) {
        DeriveResult d = derive(g, n);
        EXPECT_TRUE(d.outcome.ok()) << d.outcome.message;
        if (!d.outcome.ok()) break;
        out.push_back(toString(*d.string, g->alphabet));
    }
    return out;
}

TEST(Notation, EveryFileDerivesWhatItsLsysTwinDerives) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(SPROUT_NOTATION_DIR))
        if (e.path().extension() == ".txt") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 30u);
    const std::regex expectLine(R"(^# expect (\d+): (.*?)\r?$)"), warningLine(R"(^# warning (\d+): (.*?)\r?$)");
    int expects = 0;
    for (const auto& path : files) {
        SCOPED_TRACE(path.filename().string());
        const std::string text = slurp(path);
        ParseResult r = parseFile(path, text);
        std::set<std::string> warnings, expected;
        for (const auto& d : r.diagnostics) {
            if (d.severity == Severity::Error) ADD_FAILURE() << formatDiagnostic(d, path.filename().string());
            else if (d.message.find("was read as '-'") == std::string::npos) warnings.insert(std::to_string(d.line) + ": " + d.message);
        }
        ASSERT_TRUE(r.ok());
        EXPECT_EQ(r.grammar->dialect, "ABOP notation");

        fs::path twin = path;
        twin.replace_extension(".lsys");
        const std::string twinText = slurp(twin);
        ParseResult t = parseFile(twin, twinText);
        ASSERT_TRUE(t.ok()) << twin;
        EXPECT_TRUE(t.diagnostics.empty()) << formatDiagnostic(t.diagnostics.front(), twin.filename().string());
        EXPECT_EQ(t.grammar->dialect, ".lsys");

        const Settings& a = r.grammar->settings;
        const Settings& b = t.grammar->settings;
        EXPECT_EQ(a.iterations, b.iterations);
        EXPECT_DOUBLE_EQ(a.angle.mean, b.angle.mean);
        EXPECT_EQ(a.seed, b.seed);
        EXPECT_EQ(r.grammar->defines, t.grammar->defines);
        EXPECT_EQ(r.grammar->rules.productions.size(), t.grammar->rules.productions.size());
        EXPECT_EQ(steps(r.grammar), steps(t.grammar));

        std::istringstream lines(text);
        for (std::string line; std::getline(lines, line);) {
            std::smatch m;
            if (std::regex_match(line, m, warningLine)) {
                expected.insert(m[1].str() + ": " + m[2].str());
            } else if (std::regex_match(line, m, expectLine)) {
                EXPECT_EQ(test::expand(text, std::stoi(m[1].str())), m[2].str()) << "step " << m[1];
                ++expects;
            }
        }
        EXPECT_EQ(warnings, expected);
    }
    EXPECT_GE(expects, 20);
}

TEST(Notation, LabelsAreKeptAsWritten) {
    ParseResult r = parse("n=2, \xCE\xB4=90\xC2\xB0\n\xCF\x89: A\np\xE2\x82\x81: A \xE2\x86\x92 AB\nP2 : B \xE2\x86\x92 A\np : C -> C\nD -> D\n");
    ASSERT_TRUE(r.ok());
    const auto& p = r.grammar->rules.productions;
    ASSERT_EQ(p.size(), 4u);
    EXPECT_EQ(p[0].label, "p\xE2\x82\x81");
    EXPECT_EQ(p[1].label, "P2");
    EXPECT_EQ(p[2].label, "p");
    EXPECT_EQ(p[3].label, "");
}

TEST(Notation, EachSettingIsNamedWithItsLineAndHowItWasWritten) {
    ParseResult r = parse("n=5, \xCE\xB4=25.7\xC2\xB0\n\xCF\x89: F\nR = 1.5\nF -> F(R)\n");
    ASSERT_TRUE(r.ok());
    const auto& s = r.grammar->settingsRead;
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s[0].line, 1);
    EXPECT_EQ(s[0].name, "n");
    EXPECT_EQ(s[0].value, "5");
    EXPECT_EQ(s[1].name, "angle");
    EXPECT_EQ(s[1].written, "\xCE\xB4");
    EXPECT_EQ(s[2].name, "axiom");
    EXPECT_EQ(s[2].written, "\xCF\x89");
    EXPECT_EQ(s[3].line, 3);
    EXPECT_EQ(s[3].name, "define");
    EXPECT_EQ(r.grammar->defineOrder, std::vector<std::string>{"R"});  // a slider, as define's
    EXPECT_EQ(parse("axiom: F\nF -> FF\n").grammar->dialect, ".lsys");
    EXPECT_EQ(parse("Axiom: F\nF --> FF\n", parseOptionsFor(FileKind::Cpfg, "")).grammar->dialect, "cpfg");
    // cpfg's keywords with the web's lines (L-system Explorer's files): one warning, named.
    ParseResult web = parse("delta=20; n=2;\nderivation length: 2\naxiom: F\np0: F->F[+F]F\n", parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(web.ok());
    EXPECT_EQ(web.grammar->dialect, "L-system Explorer (cpfg family)");
    EXPECT_EQ(std::count_if(web.diagnostics.begin(), web.diagnostics.end(),
                            [](const Diagnostic& d) { return d.message.find("L-system Explorer") != std::string::npos; }),
              1);
    EXPECT_EQ(web.grammar->settings.angle.mean, 20);
}

TEST(Notation, BadInputSaysWhereAndWhat) {
    auto d = test::diagnosticsOf("p1:\nF -> FF\naxiom: F\n");
    ASSERT_FALSE(d.empty());
    EXPECT_EQ(d[0], "1:1: the label 'p1' has no rule after it: write the rule on the label's line, as in 'p1: F -> F[+F]F'");
    d = test::diagnosticsOf("\xCE\xB4 = wide\n\xCF\x89: F\n");
    ASSERT_FALSE(d.empty());
    EXPECT_EQ(d[0].substr(0, 4), "1:5:") << d[0];
    EXPECT_NE(d[0].find("wide"), std::string::npos) << d[0];
    d = test::diagnosticsOf("n = 5, \xCE\xB4 = 25.7 degrees\n\xCF\x89: F\n");
    ASSERT_FALSE(d.empty());
    EXPECT_EQ(d[0].substr(0, 2), "1:") << d[0];
    // A line after a whole rule is not more successor: a typo is an error at its line.
    d = test::diagnosticsOf("n=2, \xCE\xB4=90\xC2\xB0\n\xCF\x89: F\np1: F \xE2\x86\x92 FF\nangel 30\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].substr(0, 4), "4:1:") << d[0];
    // A constant that could be a rule: which way it was read, and how to write the other.
    d = test::diagnosticsOf("X = 2\n\xCF\x89: X\nX -> FX\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0], "1:1: warning: 'X = 2' was read as the constant X (a slider); for a rule that rewrites the module X, write 'X -> 2'");
}

// Quoted string parameters are kept as names, for the modules that take one: printed back
// as written, the same name the same number, a word before one a module of its own.
TEST(Notation, QuotedParametersAreNames) {
    const std::string text = "n: 2\naxiom: SetContour(\"leaf\") A\nA -> F(1) @Gc('ctr, 2') SetContour(\u2018leaf\u2019) A\n";
    EXPECT_EQ(test::expand(text, 1), "SetContour('leaf')F(1)@Gc('ctr, 2')SetContour('leaf')A");
    auto g = test::grammarOf(text);
    ASSERT_TRUE(g);
    EXPECT_EQ(g->alphabet.strings(), (std::vector<std::string>{"leaf", "ctr, 2"}));
    const auto id = g->alphabet.find("SetContour", 1);
    ASSERT_TRUE(id);
    EXPECT_EQ(g->alphabet[*id].nameArgs, 1u);
}

TEST(Notation, PastedTextKeepsItsColumns) {
    // A thin space and a Unicode minus before an error: the column is counted in the text as typed.
    auto d = test::diagnosticsOf("\xCF\x89:\xE2\x80\x89" "F\nF \xE2\x86\x92 F\xE2\x88\x92(F\n");
    bool found = false;
    for (const auto& m : d)
        if (m.starts_with("2:7:")) found = true;
    EXPECT_TRUE(found) << (d.empty() ? "" : d[0]);
}

}  // namespace
}  // namespace sprout
