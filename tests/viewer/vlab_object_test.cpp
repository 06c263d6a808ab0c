// The viewer opens a VLab object (issue 50): its folder, or any file in it, opens the L-system
// its cpfg line runs, drawn with the object's view and colours, and the panel gets its
// description and files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "app/plant/vlab_edit.hpp"
#include "app/viewer/state/viewer_state.hpp"

namespace sprout::viewer {
namespace {
namespace fs = std::filesystem;

TEST(ViewerVlabObject, AFolderOrAFileInItOpensTheObject) {
    const fs::path folder = fs::path(testing::TempDir()) / ("sprout_viewer_vlab_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / "specifications") << "plant.l\nplant.v\ndescription.txt\nignore:\n*\nmodel:\n\tcpfg -m plant.map plant.l plant.v plant.a\n";
    std::ofstream(folder / "plant.l") << "Lsystem: 1\nderivation length: 5\nAxiom: A\nA --> F[+A][-A]\nendlsystem\n";
    std::ofstream(folder / "plant.v") << "angle factor: 12\ninitial color: 3\nviewpoint: 1,0,0\n";
    std::ofstream(folder / "plant.a") << "first frame: 2\nlast frame: 4\n";
    std::ofstream(folder / "description.txt") << "A small shrub, for the test.\n";
    std::string map(768, '\0');
    map[9] = char(255);  // colour 3: red
    std::ofstream(folder / "plant.map", std::ios::binary) << map;

    for (const fs::path& opened : {folder, folder / "plant.v", folder / "description.txt"}) {
        ViewerState s(folder / "autosave");
        std::string error;
        ASSERT_TRUE(s.open(opened, error)) << opened << ": " << error;
        EXPECT_EQ(s.path(), folder / "plant.l") << opened;
        ASSERT_TRUE(s.vlabObject());
        EXPECT_EQ(s.vlabObject()->description, "A small shrub, for the test.\n");
        EXPECT_NE(std::find(s.vlabObject()->files.begin(), s.vlabObject()->files.end(), "plant.map"), s.vlabObject()->files.end());
        s.waitForPlant();
        ASSERT_TRUE(s.plant() && s.plant()->grammar);
        const Settings& st = s.plant()->grammar->settings;
        EXPECT_DOUBLE_EQ(st.angle.mean, 30);  // the view file's angle factor
        ASSERT_EQ(st.palette.size(), 256u);   // the colour map
        EXPECT_EQ(st.palette[3], 0xFF0000FFu);
        EXPECT_EQ(st.initialColour, 3);
        ASSERT_TRUE(st.picture);
        EXPECT_EQ(st.picture->eye, (std::array<double, 3>{1, 0, 0}));
        EXPECT_EQ(st.picture->frames, (std::vector<int>{2, 3, 4}));  // the growth slider's range
        // Every stem drawn in colour 3.
        ASSERT_FALSE(s.plant()->geometry->cylinders.empty());
        EXPECT_EQ(s.plant()->geometry->cylinders.front().colour, 0xFF0000FFu);
    }
    // Another file opened: no object any more.
    ViewerState s(folder / "autosave");
    s.openText("axiom: F\n", folder.parent_path() / "elsewhere.lsys");
    EXPECT_FALSE(s.vlabObject());
    EXPECT_FALSE(s.playing());
    // cpfg -a: the object opens playing its animation; without it, still.
    std::ofstream(folder / "specifications") << "plant.l\nmodel:\n\tcpfg -a plant.l plant.v plant.a\n";
    ViewerState playing(folder / "autosave");
    std::string error;
    ASSERT_TRUE(playing.open(folder, error)) << error;
    EXPECT_TRUE(playing.playing());
    ASSERT_TRUE(playing.vlabObject());
    EXPECT_TRUE(playing.vlabObject()->notes.empty()) << playing.vlabObject()->notes.front();
    fs::remove_all(folder);
}

// A VLab object's panel (panel.l, `panel panel.l | awkped plant.l`): the viewer shows its
// slider (vlabObject()->panels) and moving it rewrites the #define and derives again, as the
// panel's messages do in VLab.
TEST(ViewerVlabObject, APanelSliderRewritesItsDefineAndTheObjectGrowsAgain) {
    const fs::path folder = fs::path(testing::TempDir()) / ("sprout_viewer_panel_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / "specifications") << "plant.l\npanel.l\nmodel:\n\tcpfg plant.l plant.v\npanel:\n\tpanel panel.l | awkped plant.l\n";
    std::ofstream(folder / "plant.l") << "#define STEPS 2\nLsystem: 1\nderivation length: STEPS\nAxiom: A\nA --> F[+A]A\nendlsystem\n";
    std::ofstream(folder / "plant.v") << "angle factor: 8\n";
    std::ofstream(folder / "panel.l") << "target: Lsystem\npanel name: Growth\n\ntype: SLIDER\nname: Steps\nmin/max: 1 8\n"
                                          "value: 2\nmessage: d STEPS %d 1\n";
    ViewerState s(folder / "autosave");
    std::string error;
    ASSERT_TRUE(s.open(folder, error)) << error;
    ASSERT_TRUE(s.vlabObject());
    ASSERT_EQ(s.vlabObject()->panels.size(), 1u);
    ASSERT_EQ(s.vlabObject()->panels[0].items.size(), 1u);
    const auto& slider = s.vlabObject()->panels[0].items[0];
    EXPECT_TRUE(slider.slider);
    EXPECT_EQ(slider.define, "STEPS");
    s.waitForPlant();
    ASSERT_TRUE(s.plant());
    EXPECT_EQ(s.plant()->iterations, 2);
    const size_t before = s.plant()->geometry->cylinders.size();
    s.setDefineValue(slider.define, 5);  // what the panel's slider does when dragged to 5
    EXPECT_NE(s.text().find("#define STEPS 5"), std::string::npos) << s.text();
    s.waitForPlant();
    ASSERT_TRUE(s.plant());
    EXPECT_EQ(s.plant()->iterations, 5);
    EXPECT_GT(s.plant()->geometry->cylinders.size(), before);
    EXPECT_TRUE(s.vlabObject());  // still the object
    fs::remove_all(folder);
}

// Issue 50: every object of VLab's manuals opens in the viewer (File > Open on its folder) and
// its plant is derived and drawn there (the window draws the same geometry: window tests).
TEST(ViewerVlabObject, EveryManualObjectOpensAndDraws) {
    const fs::path root = fs::path(SPROUT_SHARED_DIR) / "corpus" / "vlab-manuals";
    if (!fs::is_directory(root)) GTEST_SKIP() << root << " is not here";
    std::string failures;
    int opened = 0;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        if (e.path().filename() != "specifications") continue;
        const fs::path folder = e.path().parent_path();
        ++opened;
        ViewerState s(fs::path(testing::TempDir()) / ("sprout_viewer_manual_" + std::to_string(::getpid())));
        std::string error;
        if (!s.open(folder, error)) {
            failures += "  " + folder.filename().string() + ": " + error + "\n";
            continue;
        }
        s.waitForPlant();
        const auto plant = s.plant();
        if (!s.vlabObject() || !plant || !plant->geometry ||
            plant->geometry->cylinders.size() + plant->geometry->surfaces.size() + plant->geometry->polygons.indices.size() == 0)
            failures += "  " + folder.filename().string() + ": nothing drawn\n";
    }
    EXPECT_EQ(opened, 29);
    EXPECT_TRUE(failures.empty()) << failures;
}

// The editor's files (app/plant/vlab_edit.hpp): a function in the first format (no samples of
// its own: cpfg takes the view file's count) written in funcedit's format keeps that count, so
// cpfg evaluates it as before; a function set's item and a contour are written in place.
TEST(ViewerVlabObject, TheEditorsWritesKeepWhatCpfgEvaluates) {
    const fs::path folder = fs::path(testing::TempDir()) / ("sprout_vlab_edit_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / "specifications") << "plant.l\nmodel:\n\tcpfg plant.l plant.v\n";
    std::ofstream(folder / "plant.l") << "Lsystem: 1\nderivation length: 1\nAxiom: F\nendlsystem\n";
    std::ofstream(folder / "plant.v") << "function: old.func 30\nfunction set: set.fset\ncontour: 1 c.con\n";
    std::ofstream(folder / "old.func") << "range: 0.0 1.0\npoints: 4\n0 0\n0.3 0.5\n0.7 0.5\n1 0\n";
    std::ofstream(folder / "set.fset") << "funcgalleryver 1 1\nitems: 1\nfver 1 1\nname: a\nsamples: 5\nflip: off\npoints: 4\n"
                                          "0.000000 0.000000 1\n0.300000 1.000000 1\n0.600000 1.000000 1\n1.000000 0.000000 1\n";
    std::ofstream(folder / "c.con") << "cver 1 3\nname: c\npoints: 3 3\ntype: cr\nsamples: 8\n1.000000 0.000000 0.000000 1\n"
                                       "0.000000 1.000000 0.000000 1\n-1.000000 0.000000 0.000000 1\n";
    const auto files = vlabCurveFiles((folder / "plant.l").string());
    ASSERT_EQ(files.size(), 3u);
    EXPECT_EQ(files[0].label, "old.func");
    EXPECT_EQ(files[0].samples, 30) << "the view file's count";
    EXPECT_EQ(files[1].label, "set.fset: a");
    EXPECT_EQ(files[2].label, "c.con");
    EXPECT_TRUE(files[2].rules.closed);
    std::string error;
    auto pts = files[0].points;
    pts[1][1] = 0.8;
    const auto text = vlabCurveText(files[0], pts, error);
    ASSERT_TRUE(text) << error;
    EXPECT_EQ(*text, "fver 1 1\nname: old\nsamples: 30\nflip: off\npoints: 4\n0.000000 0.000000 1\n0.300000 0.800000 1\n"
                     "0.700000 0.500000 1\n1.000000 0.000000 1\n");
    pts = files[1].points;
    pts[2][1] = 0.25;
    const auto set = vlabCurveText(files[1], pts, error);
    ASSERT_TRUE(set) << error;
    EXPECT_NE(set->find("0.600000 0.250000 1\n"), std::string::npos) << *set;
    EXPECT_EQ(set->rfind("funcgalleryver 1 1\nitems: 1\n", 0), 0u);
    const auto samples = vlabFunctionSamplesText(files[1], 50, error);
    ASSERT_TRUE(samples) << error;
    EXPECT_NE(samples->find("name: a\nsamples: 50\n"), std::string::npos) << *samples;
    EXPECT_FALSE(vlabFunctionSamplesText(files[2], 50, error)) << "a contour has none";
    EXPECT_FALSE(vlabFunctionSamplesText(files[0], 20000, error));
    pts = files[2].points;
    pts.pop_back();
    EXPECT_FALSE(vlabCurveText(files[2], pts, error)) << "a closed contour of two points";
    EXPECT_NE(error.find("3 points"), std::string::npos) << error;
    fs::remove_all(folder);
}

}  // namespace
}  // namespace sprout::viewer
