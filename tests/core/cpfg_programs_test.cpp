// cpfg's environment programs (`cpfg -e FILE.e`), provided natively
// (core/environment/cpfg_programs/): what each answers the ?E modules, on small objects of our
// own. The expected strings were obtained from the reference cpfg (VLab's, with its honda81,
// ecosystem, clover and chiba built, and the CelticKnot object's obcheck.c compiled for this check
// only) run on these same objects: `cpfg -g -str out.str -m M.map -e a.e a.l a.v`.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "core/environment/cpfg_programs/enviro_file.hpp"
#include "test_util.hpp"

namespace sprout {
namespace {

using Files = std::map<std::string, std::string>;

EnviroRead readEnviro(const Files& files) {
    auto read = [&](const std::string& name, std::string& error) -> std::optional<std::string> {
        auto it = files.find(name);
        if (it == files.end()) {
            error = "no such file";
            return std::nullopt;
        }
        return it->second;
    };
    return readEnviroText("obj/a.e", files.at("a.e"), read);
}

std::vector<std::string> messagesOf(const Files& files) {
    std::vector<std::string> out;
    for (const EnviroDiagnostic& d : readEnviro(files).diagnostics) out.push_back(d.text());
    return out;
}

// The L-system derived with the .e file's program answering its ?E, as `sprout expand` prints it.
std::string expandWith(const Files& files, const std::string& lsystem, bool warned = false, bool afterStep = false) {
    EnviroRead env = readEnviro(files);
    if (env.program) env.program->afterStep = afterStep;
    if (!warned)
        for (const EnviroDiagnostic& d : env.diagnostics) ADD_FAILURE() << d.text();
    ParseOptions o;
    o.cpfg = true;
    o.environmentProgram = env.program;
    ParseResult r = parse(lsystem, o);
    for (const auto& d : r.diagnostics) ADD_FAILURE() << formatDiagnostic(d, "a.l");
    if (!r.grammar) return "<parse error>";
    DeriveResult d = derive(r.grammar, r.grammar->settings.iterations, {});
    if (!d.outcome.ok()) return "<" + d.outcome.message + ">";
    return toString(*d.string, r.grammar->alphabet);
}

std::string enviroE(const std::string& executable, const std::string& position) {
    return "executable: " + executable + "\ncommunication type: files\nturtle position:" + position + "\n";
}

// honda81: a ?E is answered 0 where another of its group with a vigor at least its own ends
// within the radius, else 1; `3d case: on` compares x y z, off x and z.
TEST(CpfgPrograms, Honda81AnswersWhetherABranchMayGrow) {
    Files f{{"a.e", enviroE("honda81 d.spec", " %.4f %.4f %.4f")}, {"d.spec", "radius: 0.01\n3d case: on\n"}};
    EXPECT_EQ(expandWith(f, "Lsystem: 1\nderivation length: 1\nAxiom: [f(1)?E(1)][f(1.005)?E(1)][f(2)?E(0.5)][f(2.005)?E(2)]"
                            "[f(3)?E(1,1)][f(3.005)?E(1,2)][f(4)?E(1,1)][f(4.02)?E(1,1)]\n?E(v) --> R(v)\n?E(v,g) --> R(v,g)\nendlsystem\n"),
              "[f(1)R(0)][f(1.005)R(0)][f(2)R(0)][f(2.005)R(1)][f(3)R(1,1)][f(3.005)R(1,2)][f(4)R(1,1)][f(4.02)R(1,1)]");
    f["d.spec"] = "radius: 0.5\n";  // 2d: x and z
    EXPECT_EQ(expandWith(f, "Lsystem: 1\nderivation length: 1\nAxiom: [&(90)f(1)?E(1)][f(1)?E(1)][f(2)?E(1)][^(90)f(2)?E(3)]"
                            "[^(90)f(2.4)?E(2)]\n?E(v) --> R(v)\nendlsystem\n"),
              "[&(90)f(1)R(1)][f(1)R(0)][f(2)R(0)][^(90)f(2)R(1)][^(90)f(2.4)R(0)]");
}

// ecosystem: a disc of radius ?E's first parameter, answered 0 where it meets a bigger one of its
// group (with `vigor: on`, one of higher vigor), else 1. '3D case' is not its setting: 2d.
TEST(CpfgPrograms, EcosystemAnswersWhetherADiscIsDominated) {
    Files f{{"a.e", enviroE("ecosystem -e a.e e.spec", " %.4f %.4f %.4f")}, {"e.spec", "grid size: 10 10 10\nvigor: off\n"}};
    EXPECT_EQ(expandWith(f, "Lsystem: 1\nderivation length: 1\nAxiom: [&(90)f(1)?E(0.3)][&(90)f(1.5)?E(0.2)][f(7)?E(0.2)]"
                            "[^(90)f(3)?E(0.25)][^(90)f(3.5)?E(0.25)][+(90)f(3)?E(0.5,1)][+(90)f(3.2)?E(0.1,2)][-(90)f(9)?E(0.1)]"
                            "[-(90)f(9.15)?E(0.05)]\n?E(v) --> R(v)\n?E(v,g) --> R(v,g)\nendlsystem\n"),
              "[&(90)f(1)R(1)][&(90)f(1.5)R(0)][f(7)R(1)][^(90)f(3)R(0)][^(90)f(3.5)R(0)][+(90)f(3)R(1,1)][+(90)f(3.2)R(1,2)]"
              "[-(90)f(9)R(1)][-(90)f(9.15)R(0)]");
    f["e.spec"] = "grid size: 4 4 4\n3d case: on\nvigor: on\n";  // a ?E without its vigor is not answered
    EXPECT_EQ(expandWith(f, "Lsystem: 1\nderivation length: 1\nAxiom: [f(1)?E(0.3,1)][f(1.5)?E(0.3,2)][f(2)?E(0.3,3)]"
                            "[f(5)?E(0.2,1)][f(5.3)?E(0.3,1)][+(90)f(3)?E(0.5)][+(90)f(3.4)?E(0.2)]\n?E(v) --> R(v)\n?E(v,g) --> R(v,g)\nendlsystem\n"),
              "[f(1)R(0,1)][f(1.5)R(0,2)][f(2)R(1,3)][f(5)R(0,1)][f(5.3)R(1,1)][+(90)f(3)R(0.5)][+(90)f(3.4)R(0.2)]");
    f["e.spec"] = "grid size: 10 10 10\n3D case: on\n";
    EXPECT_EQ(messagesOf(f), std::vector<std::string>{"obj/e.spec:2:1: warning: ecosystem has no setting '3D case' (it passes "
                                                      "over this line); did you mean '3d case'? Its settings: 'verbose', "
                                                      "'grid size', '3d case', 'vigor'"});
    f["e.spec"] = "grid size: 3000000000 3000000000 3000000000\n3d case: on\n";  // each taken as 2e9; their product must not overflow
    EXPECT_EQ(messagesOf(f), std::vector<std::string>{"obj/e.spec:1:1: 'grid size': 2000000000 x 2000000000 x 2000000000 cells "
                                                      "is over Sprout's 16000000 for ecosystem's grid"});
}

// A 4 x 4 SGI image (RLE, three channels): red 10x + 40y, green 255 - 16(x + 4y).
std::string sgiImage() {
    std::string out(512, '\0');
    auto put16 = [&](size_t at, unsigned v) { out[at] = char(v >> 8), out[at + 1] = char(v & 255); };
    put16(0, 474), out[2] = 1, out[3] = 1, put16(4, 3), put16(6, 4), put16(8, 4), put16(10, 3);
    std::string table(8 * 12, '\0'), data;
    for (unsigned r = 0; r < 12; ++r) {
        const unsigned z = r / 4, y = r % 4;
        const unsigned start = unsigned(512 + table.size() + data.size());
        for (int k = 0; k < 4; ++k) table[4 * r + unsigned(k)] = char(start >> (24 - 8 * k));
        table[48 + 4 * r + 3] = char(6);
        data += char(0x80 | 4);
        for (unsigned x = 0; x < 4; ++x) data += char(z == 0 ? 10 * x + 40 * y : z == 1 ? 255 - 16 * (x + 4 * y) : 0);
        data += '\0';
    }
    return out + table + data;
}

// clover: ?E(1, area) lays a leaf, ?E(2, area) takes one away, and stay from step to step; ?E(0)
// and ?E(0, r) are answered the image's light there times transmittance^leaves (and red/128).
TEST(CpfgPrograms, CloverAnswersTheLightUnderTheLeaves) {
    Files f{{"a.e", "executable: clover -e a.e c.spec\ncommunication type: memory\nturtle position:P:%g %g %g\n"},
            {"c.spec", "grid position: -2 -2\ngrid range: 4x4\ngrid size: 4x4\ninput image: l.rgb\ntransmittance: 0.5\n"},
            {"l.rgb", sgiImage()}};
    EXPECT_EQ(expandWith(f, "Lsystem: 1\nderivation length: 4\nAxiom: [f(0.5)?E(1,3)][+(90)f(1.5)?E(0,0)]?E(0)T(0)\n"
                            "?E(x) --> R(x)?E(x)\nT(n) : n==1 --> [f(0.5)?E(2,3)]T(2)\nT(n) --> T(n+1)\nendlsystem\n"),
              "[f(0.5)?E(1,3)][+(90)f(1.5)?E(0.498039,0.625)]R(0.186275)R(0.0931373)R(0.0931373)R(0.0931373)?E(0.0931373)"
              "[f(0.5)?E(2,3)]T(4)");
    // A leaf 100,000 cells across: the cells near its rim are under it, as at its centre
    // (clover.c's int squares of the cells' offsets overflowed past 46,340: none were).
    f["c.spec"] = "grid position: -2 -2\ngrid range: 4x4\ngrid size: 2x100000\ninput image: l.rgb\ntransmittance: 0.5\n";
    EXPECT_EQ(expandWith(f, "Lsystem: 1\nderivation length: 1\nAxiom: ?E(1,12.566)[f(1.9)?E(0)][+(180)f(1.9)?E(0)]"
                            "[f(1)?E(0)]\nendlsystem\n"),
              "?E(1,12.566)[f(1.9)?E(0.154902)][+(180)f(1.9)?E(0.405882)][f(1)?E(0.154902)]");
    // A truncated image, or one of another kind: said, and full light taken.
    f["l.rgb"] = sgiImage().substr(0, 620);
    EXPECT_EQ(messagesOf(f), std::vector<std::string>{"obj/c.spec:4:1: warning: 'input image': l.rgb: row 3 of channel 1 of the SGI image lies "
                                                      "beyond the file's end (truncated); full light is taken everywhere"});
    f["c.spec"] = "grid size: 1x100\ninput image: l.png\n";
    EXPECT_EQ(messagesOf(f), std::vector<std::string>{"obj/c.spec:1:1: 'grid size': expected at least 2 x 2 cells and at most "
                                                      "64000000 in all, not 1 x 100"});
    f["c.spec"] = "grid range: 4 wide\ninput image: l.png\n";
    EXPECT_EQ(messagesOf(f), (std::vector<std::string>{
                                 "obj/c.spec:1:1: warning: 'grid range': expected the grid's width and height, not 'wide' (read as 0)",
                                 "obj/c.spec:2:1: warning: 'input image': Sprout's clover reads SGI images (.rgb), not l.png; "
                                 "full light is taken everywhere"}));
}

// chiba: the light reaching each sphere ?E(radius) (0: the file's radius) from the sky's samples
// or the given sources, and with four parameters the brightest direction.
TEST(CpfgPrograms, ChibaAnswersTheLightReachingEachSphere) {
    Files f{{"a.e", enviroE("chiba c.spec", " %g %g %g")}, {"c.spec", "grid size: 4 4 4\nnumber of samples: 32\nradius: 0.5\n"}};
    const std::string lsystem = "Lsystem: 1\nderivation length: 1\nAxiom: [?E(1,0,0,0)][f(1.5)?E(0)][f(3)?E(0.8)][+(80)f(1.1)?E(0.6,0,0,0)]"
                                "[&(90)f(2)?E(1)]\n?E(v) --> R(v)\n?E(v,x,y,z) --> R(v,x,y,z)\nendlsystem\n";
    EXPECT_EQ(expandWith(f, lsystem), "[R(0.9446,0.364185,0.906025,0.215611)][f(1.5)R(0.920784)][f(3)R(1)]"
                                      "[+(80)f(1.1)R(0.92405,-0.523687,0.84999,0.0571683)][&(90)f(2)R(0.964977)]");
    f["c.spec"] = "grid size: 3 3 3\nsource direction: 0 1 0 2\nsource direction: 1 1 0 1\nestimate intersection area: on\n";
    EXPECT_EQ(expandWith(f, lsystem), "[R(0.482463,0.316482,0.948598,0)][f(1.5)R(0.99959)][f(3)R(1)]"
                                      "[+(80)f(1.1)R(0.525629,0.21863,0.975808,0)][&(90)f(2)R(0.6)]");
    f["c.spec"] = "grid size: 0 4 4\n";
    EXPECT_EQ(messagesOf(f), std::vector<std::string>{"obj/c.spec:1:1: 'grid size': expected three whole numbers of voxels, at "
                                                      "least 1 each and 16000000 in all at most"});
    f["c.spec"] = "grid size: 3 4444444444 4444444444\n";  // as fuzz_enviro found it: the product overflowed
    EXPECT_EQ(messagesOf(f), std::vector<std::string>{"obj/c.spec:1:1: 'grid size': expected three whole numbers of voxels, at "
                                                      "least 1 each and 16000000 in all at most"});
}

// obcheck (the CelticKnot object's program): ?E(0) starts a segment, ?E(v) ends it and is answered
// whether it crosses an obstacle of obstacles.dat; at once, in the turtle's order.
TEST(CpfgPrograms, ObcheckAnswersWhetherAPathCrossesAnObstacle) {
    Files f{{"a.e", enviroE("./obcheck -e a.e o.dat", "P:%.4f %.4f")},
            {"o.dat", "line width: 0.05\ncoordinates:\n-0.5 1 0.5 1\n\n3 0 3 5\n"}};
    EXPECT_EQ(expandWith(f, "Lsystem: 1\nderivation length: 2\nAxiom: ?E(0)f(2)?E(1)?E(0)-(90)f(2)?E(1)f(2)?E(1)+(90)f(1)?E(5)\n"
                            "?E(x) --> R(x)?E(x)\nendlsystem\n"),
              "R(0)R(0)?E(0)f(2)R(1)R(1)?E(1)R(0)R(0)?E(0)-(90)f(2)R(0)R(0)?E(0)f(2)R(1)R(1)?E(1)+(90)f(1)R(1)R(1)?E(1)");
    f["o.dat"] = "coordinates:\n0 1 2 3\n4 5 six 7\n";
    EXPECT_EQ(messagesOf(f), std::vector<std::string>{"obj/o.dat:3:1: warning: expected an obstacle's four numbers (x1 y1 x2 y2); "
                                                      "obcheck stops reading here, with 1 obstacles"});
}

// The .e file itself: a program Sprout does not provide is named (?E keeps its values), and so
// are a format that is not a number's, a setting cpfg does not have, a missing specification.
TEST(CpfgPrograms, TheEnvironmentFileSaysWhatItCannotRun) {
    Files f{{"a.e", enviroE("./soil -e a.e s.spec", " %g %g %g")}};
    EXPECT_EQ(messagesOf(f), std::vector<std::string>{"obj/a.e:1:1: warning: the environment program 'soil' is not one Sprout "
                                                      "provides (it provides honda81, ecosystem, clover, chiba and obcheck): ?E keeps "
                                                      "its values"});
    EXPECT_EQ(expandWith(f, "Lsystem: 1\nderivation length: 2\nAxiom: ?E(3)\n?E(x) --> F?E(x+1)\nendlsystem\n", true), "FF?E(5)");
    f = {{"a.e", "executable: honda81 d.spec\nturtle position: %d %s\ncommunication type: smoke\nturtle colour: %g\n"}};
    EXPECT_EQ(messagesOf(f), (std::vector<std::string>{
                                 "obj/a.e:2:1: warning: 'turtle position': expected a number's conversion (%f, %g or %e, with a width "
                                 "and a precision if any) at '%d'; the program is not sent it",
                                 "obj/a.e:3:1: warning: 'communication type': expected files, memory, pipes or sockets, not 'smoke' "
                                 "(cpfg uses pipes; in Sprout the program answers alike whichever)",
                                 "obj/a.e:4:1: warning: cpfg's .e files have no setting 'turtle colour' (cpfg passes over this line)",
                                 "obj/a.e:1:1: warning: honda81's specification file d.spec cannot be read: no such file; it takes "
                                 "its defaults"}));
    EXPECT_EQ(messagesOf({{"a.e", "communication type: files\n"}}),
              std::vector<std::string>{"obj/a.e: warning: no 'executable: PROGRAM ARGUMENTS' line names the environment program: "
                                       "the environment is left out (cpfg leaves it out too) and ?E keeps its values"});
    EXPECT_EQ(messagesOf({{"a.e", "executable: obcheck\n"}}),
              std::vector<std::string>{"obj/a.e:1:1: warning: obcheck takes its specification file: 'executable: obcheck FILE'; it "
                                       "does not start, and ?E keeps its values"});
    EXPECT_EQ(readEnviroFile("/nonexistent/a.e").diagnostics.at(0).diagnostic.severity, Severity::Error);
}

// When the program is asked: as each step begins, of the string before it (cpfg's default), so a
// step's string shows its ?E as the rules wrote them; or, with the view file's `environment
// display: before`, on the axiom and after each step, so the string shows the answers.
TEST(CpfgPrograms, TheViewFileSaysWhenTheProgramIsAsked) {
    Files f{{"a.e", enviroE("honda81 d.spec", " %.4f %.4f %.4f")}, {"d.spec", "radius: 0.5\n3d case: on\n"}};
    const std::string lsystem = "Lsystem: 1\nderivation length: 3\nAxiom: ?E(1)\n?E(x) : x==1 --> [+(60)F?E(0)][-(60)F?E(0)]\nendlsystem\n";
    EXPECT_EQ(expandWith(f, lsystem), "[+(60)F[+(60)F[+(60)F?E(0)][-(60)F?E(0)]][-(60)F[+(60)F?E(0)][-(60)F?E(0)]]][-(60)F[+(60)F"
                                      "[+(60)F?E(0)][-(60)F?E(0)]][-(60)F[+(60)F?E(0)][-(60)F?E(0)]]]");
    EXPECT_EQ(expandWith(f, lsystem, false, true), "[+(60)F[+(60)F[+(60)F?E(1)][-(60)F?E(1)]][-(60)F[+(60)F?E(1)][-(60)F?E(0)]]]"
                                                   "[-(60)F[+(60)F[+(60)F?E(0)][-(60)F?E(1)]][-(60)F[+(60)F?E(1)][-(60)F?E(1)]]]");
}

// The manual's Sierpinski object (honda81): cpfg's string at 6 steps.
TEST(CpfgPrograms, TheSierpinskiObjectGivesCpfgsString) {
    const std::filesystem::path folder = std::filesystem::path(SPROUT_SHARED_DIR) / "corpus/vlab-manuals/20-EnviroPgms/CPFG-Sierpinski";
    if (!std::filesystem::exists(folder / "fractal.e")) GTEST_SKIP() << "no " << folder;
    EnviroRead env = readEnviroFile((folder / "fractal.e").string());
    ASSERT_TRUE(env.program);
    EXPECT_TRUE(env.diagnostics.empty());
    ParseOptions o;
    o.cpfg = true;
    o.environmentProgram = env.program;
    ParseResult r = parse(test::slurp(folder / "fractal.l"), o);
    ASSERT_TRUE(r.grammar);
    DeriveResult d = derive(r.grammar, 6, {});
    ASSERT_TRUE(d.outcome.ok());
    EXPECT_EQ(toString(*d.string, r.grammar->alphabet),
              "|+(30);[F;[F;[F;[F;[F;[F?E(0)]-(60)/(180)[F?E(0)]]-(60)/(180)[F;[F?E(0)]-(60)/(180)[F?E(0)]]]-(60)/(180)[F?E(0)]]"
              "-(60)/(180)[F;[F?E(0)]-(60)/(180)[F?E(0)]]]-(60)/(180)[F?E(0)]]-(60)/(180)[F;[F;[F;[F;[F;[F?E(0)]-(60)/(180)"
              "[F?E(0)]]-(60)/(180)[F;[F?E(0)]-(60)/(180)[F?E(0)]]]-(60)/(180)[F?E(0)]]-(60)/(180)[F;[F?E(0)]-(60)/(180)"
              "[F?E(0)]]]-(60)/(180)[F?E(0)]]");
}

}  // namespace
}  // namespace sprout
