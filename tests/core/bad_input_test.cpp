// tests/bad-input: malformed grammars, each with the first message Sprout must give and its
// position; plus the extremes (a million brackets, NaN and infinity in parameters).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/derive/derive.hpp"
#include "core/language/file_kind.hpp"
#include "core/language/grammar.hpp"
#include "core/turtle/turtle.hpp"

namespace sprout {
namespace {

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

struct FolderCount {
    int files = 0, malformed = 0, drawn = 0;
};

// Every grammar in `dir` against its line in dir/expected.tsv: FILE, then where ("L:C" for the
// first message of the parse, "derive" for a derivation that must stop with the message,
// "ok" for one that must derive and draw), then the message.
FolderCount checkFolder(const std::filesystem::path& dir) {
    FolderCount count;
    std::map<std::string, std::pair<std::string, std::string>> expected;
    std::istringstream table(slurp(dir / "expected.tsv"));
    for (std::string line; std::getline(table, line);) {
        if (line.empty() || line[0] == '#') continue;
        size_t a = line.find('\t'), b = line.find('\t', a + 1);
        EXPECT_NE(b, std::string::npos) << line;
        if (b == std::string::npos) continue;
        expected[line.substr(0, a)] = {line.substr(a + 1, b - a - 1), line.substr(b + 1)};
    }
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const auto ext = entry.path().extension();
        if (ext != ".lsys" && ext != ".l" && ext != ".lpy") continue;
        const std::string name = entry.path().filename().string();
        SCOPED_TRACE(name);
        ++count.files;
        auto it = expected.find(name);
        if (it == expected.end()) {
            ADD_FAILURE() << "no line for it in expected.tsv";
            continue;
        }
        const auto& [where, message] = it->second;
        // Through the one way in: what the file is comes from its content (cpfg-family files
        // are .l and .lpy here), #include reads beside it.
        const std::string text = slurp(entry.path());
        const FileKind kind = detectFileKind(entry.path().string(), text);
        if (ext != ".lsys") {
            EXPECT_TRUE(cpfgFamily(kind));
        }
        ParseResult r = parse(text, parseOptionsFor(kind, entry.path().string()));
        if (where == "ok" || where == "derive") {
            if (!r.ok()) {
                ADD_FAILURE() << (r.diagnostics.empty() ? "" : r.diagnostics[0].message);
                continue;
            }
            Derivation d(r.grammar);
            const int n = r.grammar->settings.iterations;
            DeriveOutcome o = d.deriveTo(n);
            if (where == "derive") {
                ++count.malformed;
                EXPECT_FALSE(o.ok());
                EXPECT_EQ(o.message, message);
            } else {
                EXPECT_TRUE(o.ok()) << o.message;
                if (!o.ok()) continue;
                Geometry g;
                interpret(*d.step(n), *r.grammar, {n, d.seed(), nullptr}, g);
                if (!g.cylinders.empty() || !g.surfaces.empty()) ++count.drawn;
            }
            continue;
        }
        ++count.malformed;
        if (r.diagnostics.empty()) {
            ADD_FAILURE() << "accepted without a word";
            continue;
        }
        const Diagnostic& first = r.diagnostics.front();
        EXPECT_EQ(std::to_string(first.line) + ":" + std::to_string(first.col), where);
        EXPECT_EQ((first.severity == Severity::Warning ? "warning: " : "") + first.message, message);
    }
    EXPECT_EQ(count.files, int(expected.size())) << "expected.tsv names files that are not there";
    return count;
}

TEST(BadInput, EveryFileGetsItsMessageAtItsPosition) {
    EXPECT_GE(checkFolder(SPROUT_BAD_INPUT_DIR).malformed, 50);
}

// tests/extreme (issue 26): huge, tiny, zero, negative, NaN and infinite numbers in every
// environment form, and plants 1e30 long meeting each kind of environment. Each ends in a
// drawing or a message at its position; the sanitizer build replays them (float-cast-overflow
// included) to show no number on the way became an integer without bounds.
TEST(BadInput, ExtremeNumbersEndInADrawingOrAMessage) {
    const FolderCount c = checkFolder(SPROUT_EXTREME_DIR);
    EXPECT_GE(c.files, 12);
    EXPECT_GE(c.drawn, 4);
    EXPECT_GE(c.malformed, 8);
}

TEST(BadInput, AMillionNestedBracketsDeriveAndDraw) {
    const std::string deep(1000000, '[');
    ParseResult r = parse("axiom: " + deep + "F" + std::string(1000000, ']') + "\n");
    ASSERT_TRUE(r.ok());
    Derivation d(r.grammar);
    ASSERT_TRUE(d.deriveTo(0).ok());
    Geometry g;
    interpret(*d.step(0), *r.grammar, {0, 1, nullptr}, g);
    EXPECT_EQ(g.cylinders.size(), 1u);
    // Unclosed: an error at the first bracket that is never closed.
    ParseResult open = parse("axiom: F" + deep + "\n");
    ASSERT_FALSE(open.ok());
    EXPECT_EQ(open.diagnostics[0].line, 1);
    EXPECT_NE(open.diagnostics[0].message.find("never closed"), std::string::npos);
}

TEST(BadInput, NanAndInfinityInParametersAreNotDrawn) {
    // Parameters that overflow while deriving: the turtle skips what is not finite.
    ParseResult r = parse("n: 3\naxiom: A(1e300)\nA(x) -> F(x)+(x)A(x*x)F(1)\n");
    ASSERT_TRUE(r.ok());
    Derivation d(r.grammar);
    ASSERT_TRUE(d.deriveTo(3).ok());
    Geometry g;
    interpret(*d.step(3), *r.grammar, {3, 1, nullptr}, g);
    for (const auto& c : g.cylinders) {
        ASSERT_TRUE(std::isfinite(c.start.x) && std::isfinite(c.start.y) && std::isfinite(c.start.z));
        ASSERT_TRUE(std::isfinite(c.end.x) && std::isfinite(c.end.y) && std::isfinite(c.end.z));
    }
    EXPECT_TRUE(std::isfinite(g.bounds.min.x) && std::isfinite(g.bounds.max.y));
    // 0/0 while deriving is NaN: also skipped.
    ParseResult z = parse("n: 2\naxiom: A(0)\nA(x) -> F(x/x)A(x)F(1)\n");
    ASSERT_TRUE(z.ok());
    Derivation dz(z.grammar);
    ASSERT_TRUE(dz.deriveTo(2).ok());
    interpret(*dz.step(2), *z.grammar, {2, 1, nullptr}, g);
    for (const auto& c : g.cylinders) ASSERT_TRUE(std::isfinite(c.end.y));
}

}  // namespace
}  // namespace sprout
