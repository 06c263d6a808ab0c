// The panel's editors on a VLab object's own files (issue 52), under Xvfb: a function and a
// contour dragged change the picture and are written in funcedit's and cuspy's formats; the
// editor's undo gives back the picture and the files byte for byte.
#include <fstream>
#include <sstream>

#include "tests/viewer/window_support.hpp"

namespace sprout {
namespace {

TEST(Window, AnObjectsFunctionAndContourDraggedChangeThePlantAndUndoRestoresTheirFiles) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    const fs::path dir = testDir("object_editors");
    const fs::path object = dir / "object";
    fs::create_directories(object);
    std::ofstream(object / "specifications") << "plant.l\nplant.v\nlen.func\nsec.con\nmodel:\n\tcpfg plant.l plant.v\n";
    // A tube whose segments' lengths follow function 1, its section contour 1 (a flat oval).
    std::ofstream(object / "plant.l") << "#define N 8\nLsystem: 1\nderivation length: 8\nAxiom: #(1.5) @#(1) @Gs A(0) @Ge\n"
                                         "A(t) : t < N --> F(0.3 + 2*func(1, t/N)) +(12) A(t+1)\nendlsystem\n";
    std::ofstream(object / "plant.v") << "function: len.func\ncontour: 1 sec.con\ncontour sides: 12\nline style: cylinder\n";
    const std::string func = "fver 1 1\nname: len\nsamples: 10\nflip: off\npoints: 4\n0.000000 0.200000 1\n0.333333 0.200000 1\n"
                             "0.666667 0.200000 1\n1.000000 0.200000 1\n";
    const std::string con = "cver 1 3\nname: sec\npoints: 4 4\ntype: cr\nsamples: 8\n1.000000 0.300000 0.000000 1\n"
                            "1.000000 -0.300000 0.000000 1\n-1.000000 -0.300000 0.000000 1\n-1.000000 0.300000 0.000000 1\n";
    std::ofstream(object / "len.func", std::ios::binary) << func;
    std::ofstream(object / "sec.con", std::ios::binary) << con;
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string(), c = (dir / "c.png").string(),
                      d = (dir / "d.png").string();
    const fs::path movedFunc = dir / "moved.func", movedCon = dir / "moved.con";
    const auto printed = runScript(dir, (object / "plant.l").string() + " --size 1000x700",
                                   "wait\nobject-curves\nscreenshot " + a + " 400x300\n"
                                   // one drag of the function's third point, in two moves: one undo step
                                   "object-point 0 2 0.9 0.7 5\nobject-point 0 2 0.666667 1.2 5\nwait\nscreenshot " + b + " 400x300\n"
                                   "object-point 1 0 2.5 2.5\nwait\nscreenshot " + c + " 400x300\nobject-curves\n"
                                   "object-undo\nobject-undo\nwait\nscreenshot " + d + " 400x300\nquit\n");
    ASSERT_EQ(printed.size(), 4u);
    EXPECT_EQ(printed[0], "object-curve=len.func points=0,0.200000003,1;0.333332986,0.200000003,1;0.666666985,0.200000003,1;1,0.200000003,1");
    EXPECT_EQ(printed[1], "object-curve=sec.con points=1,0.300000012,1;1,-0.300000012,1;-1,-0.300000012,1;-1,0.300000012,1");
    EXPECT_EQ(printed[2], "object-curve=len.func points=0,0.200000003,1;0.333332986,0.200000003,1;0.666666985,1.20000005,1;1,0.200000003,1")
        << "x stays between its neighbours; y as dragged";
    EXPECT_EQ(printed[3], "object-curve=sec.con points=2.5,2.5,1;1,-0.300000012,1;-1,-0.300000012,1;-1,0.300000012,1");
    const Image ia = load(a), ib = load(b), ic = load(c), id = load(d);
    EXPECT_GT(pixelsThatDiffer(ia, ib), 400u * 300u / 100) << "longer segments where the function rose";
    EXPECT_GT(pixelsThatDiffer(ib, ic), 400u * 300u / 100) << "a thicker tube where the contour grew";
    EXPECT_LE(pixelsThatDiffer(ia, id), 20u) << "two undos: the plant as it was";
    EXPECT_EQ(fileText(object / "len.func"), func) << "the function's file byte for byte";
    EXPECT_EQ(fileText(object / "sec.con"), con) << "the contour's file byte for byte";
}

// The Colours section on a colour map (palette's .map): entry 1, the stem's, set to red in the
// file; an interpolated range; undo gives back the map byte for byte.
TEST(Window, AnObjectsColourMapEntrySetRecoloursThePlantAndUndoRestoresTheMap) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    const fs::path dir = testDir("object_colours");
    const fs::path object = dir / "object";
    fs::create_directories(object);
    std::ofstream(object / "specifications") << "plant.l\nplant.v\nplant.map\nmodel:\n\tcpfg -m plant.map plant.l plant.v\n";
    std::ofstream(object / "plant.l") << "Lsystem: 1\nderivation length: 0\nAxiom: #(0.6) ;(1) F(4)\nendlsystem\n";
    std::ofstream(object / "plant.v") << "line style: cylinder\n";
    std::string map(768, char(90));
    map[3] = 20, map[4] = char(200), map[5] = 20;  // entry 1: green
    std::ofstream(object / "plant.map", std::ios::binary) << map;
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string(), c = (dir / "c.png").string();
    const auto printed = runScript(dir, (object / "plant.l").string() + " --size 1000x700",
                                   "wait\ncolours\nscreenshot " + a + " 400x300\ncolour-set 0 1 colour 230 20 20\nwait\n"
                                   "screenshot " + b + " 400x300\ncolour-set 0 10 interpolate 20\nwait\ncolours\n"
                                   "object-undo\nobject-undo\nwait\nscreenshot " + c + " 400x300\nquit\n");
    ASSERT_EQ(printed.size(), 2u);
    EXPECT_EQ(printed[0], "colour-file=plant.map (colour map, set 1) entries=5A5A5A,14C814,5A5A5A,5A5A5A...");
    EXPECT_EQ(printed[1], "colour-file=plant.map (colour map, set 1) entries=5A5A5A,E61414,5A5A5A,5A5A5A...");
    const Image ia = load(a), ib = load(b), ic = load(c);
    const auto ma = mean(ia, 190, 120, 210, 180), mb = mean(ib, 190, 120, 210, 180);
    EXPECT_GT(ma[1], ma[0] + 40) << "green first";
    EXPECT_GT(mb[0], mb[1] + 40) << "red once set";
    EXPECT_LE(pixelsThatDiffer(ia, ic), 20u);
    EXPECT_EQ(fileText(object / "plant.map"), map) << "two undos: the map byte for byte";
}

// The surface editor on a VLab object's .s file: a control point of its Bezier patch moved,
// written as bezieredit writes it, the leaf drawn anew; the section's undo gives the file back.
TEST(Window, AnObjectsSurfacePointMovedChangesTheLeafAndUndoRestoresTheFile) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    const fs::path dir = testDir("object_surface");
    const fs::path object = dir / "object";
    fs::create_directories(object);
    std::ofstream(object / "specifications") << "plant.l\nplant.v\nleaf.s\nmodel:\n\tcpfg plant.l plant.v\n";
    std::ofstream(object / "plant.l") << "Lsystem: 1\nderivation length: 0\nAxiom: F(1) ~l(3)\nendlsystem\n";
    std::ofstream(object / "plant.v") << "surface: l leaf.s 1\n";
    const std::string leaf = "-1 1\t0 2\t0 0\nCONTACT POINT  X: 0 Y: 0 Z: 0\nEND POINT      X: 0 Y: 2 Z: 0\n"
                             "HEADING        X: 0 Y: 1 Z: 0\nUP             X: 0 Y: 0 Z: 1\nSIZE: 2\nleaf\n"
                             "TOP COLOR: 0 DIFFUSE: 0.0 BOTTOM COLOR: 0 DIFFUSE: 0.0\nAL: ~ A: ~ AR: ~\nL: ~ R: ~\nBL: ~ B: ~ BR: ~\n"
                             "0 0 0\t0 0 0\t0 0 0\t0 0 0\t\n-0.5 0.7 0\t-0.2 0.7 0\t0.2 0.7 0\t0.5 0.7 0\t\n"
                             "-0.5 1.4 0\t-0.2 1.4 0\t0.2 1.4 0\t0.5 1.4 0\t\n0 2 0\t0 2 0\t0 2 0\t0 2 0\t\n";
    std::ofstream(object / "leaf.s", std::ios::binary) << leaf;
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string(), c = (dir / "c.png").string();
    const auto printed = runScript(dir, (object / "plant.l").string() + " --size 1000x700",
                                   "wait\nsurfaces\nscreenshot " + a + " 400x300\nsurface-point 0 1 0 -1.5 0.7 0\n"
                                   "surface-point 0 2 0 -1.5 1.4 0\nwait\nscreenshot " + b + " 400x300\nsurfaces\n"
                                   "object-undo\nobject-undo\nwait\nscreenshot " + c + " 400x300\nquit\n");
    ASSERT_EQ(printed.size(), 2u);
    EXPECT_NE(printed[1].find(";-1.5,0.7,0;"), std::string::npos) << printed[1];
    EXPECT_NE(printed[1].find(";-1.5,1.4,0;"), std::string::npos) << printed[1];
    const Image ia = load(a), ib = load(b), ic = load(c);
    EXPECT_GT(pixelsThatDiffer(ia, ib), 400u * 300u / 200) << "a wider leaf";
    EXPECT_LE(pixelsThatDiffer(ia, ic), 20u);
    EXPECT_EQ(fileText(object / "leaf.s"), leaf) << "two undos: bezieredit's file byte for byte";
}

// Sprout's own grammar's function, in the same editor: its middle point dragged down shortens
// the tube's middle segments; one undo gives back the picture and the text.
TEST(Window, AnLsysFunctionDraggedChangesThePlantAndUndoRestoresTheText) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    const fs::path dir = testDir("lsys_function");
    const fs::path model = dir / "tube.lsys", moved = dir / "moved.lsys", back = dir / "back.lsys";
    const std::string text = "n: 6\nangle: 20\nfunction: len 0,0.2 0.5,1 1,0.2\ncontour: 1 closed 1,0.3 1,-0.3 -1,-0.3 -1,0.3\n"
                             "axiom: #(1.5) @#(1) @Gs A(0) @Ge\nA(t) : t < 6 -> F(0.3 + 2*func(len, t/6)) +(12) A(t+1)\n";
    std::ofstream(model, std::ios::binary) << text;
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string(), c = (dir / "c.png").string();
    const auto printed = runScript(dir, model.string() + " --size 1000x700",
                                   "wait\ncurves\nscreenshot " + a + " 400x300\ncurve-point len 1 0.5 0.1 1\ncurve-point len 1 0.7 0.1 1\n"
                                   "wait\nscreenshot " + b + " 400x300\ncurves\nsaveas " + moved.string() + "\nundo\nwait\nscreenshot " + c +
                                   " 400x300\nsaveas " + back.string() + "\nquit\n");
    EXPECT_EQ(printed, (std::vector<std::string>{"curve=len kind=function points=0,0.2;0.5,1;1,0.2",
                                                 "curve=1 kind=contour points=1,0.3;1,-0.3;-1,-0.3;-1,0.3",
                                                 "curve=len kind=function points=0,0.2;0.7,0.1;1,0.2",
                                                 "curve=1 kind=contour points=1,0.3;1,-0.3;-1,-0.3;-1,0.3"}));
    const Image ia = load(a), ib = load(b), ic = load(c);
    EXPECT_GT(pixelsThatDiffer(ia, ib), 400u * 300u / 100) << "a shorter tube";
    EXPECT_LE(pixelsThatDiffer(ia, ic), 20u);
    std::string expected = text;
    expected.replace(expected.find("0.5,1"), 5, "0.7,0.1");
    EXPECT_EQ(fileText(moved), expected) << "only the line's points change";
    EXPECT_EQ(fileText(back), text);
}

}  // namespace
}  // namespace sprout
