// A VLab object's control panel (issue 50): its sliders and buttons read as VLab's panel sends
// them to awkped (`d NAME %d DIVISOR`: the #define becomes the value over the divisor), the
// panels found from the specifications' `panel FILE | awkped LSYSTEM`, and a wrong line named.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "app/plant/vlab_panel.hpp"

namespace {

using namespace sprout;

const char* kPanel =
    "target: Lsystem\npanel name: Model parameters\nbackground: 0,0,0\n\n"
    "type: SLIDER\nname: Segment length\ncolors: 255,255,255 255,0,0\norigin: 20 139\n"
    "min/max: 50 150\nvalue: 100\nmessage: d S0 %d 100\n\n"
    "type: BUTTON\nname: Left\ntricolor: 255,255,255 0,0,255 0,0,0\norigin: 36 18\nvalue: 1\nmessage: d LEFT 1 1\n\n"
    "type: LABEL\nname: a label\n\n"
    "type: SLIDER\nname: Steps\nmin/max: zero 300\nvalue: 300\nmessage: d STEPS %d 1\n";

TEST(VlabPanel, SlidersAndButtonsRewriteTheirDefines) {
    const VlabPanel p = readVlabPanel(kPanel, "panel.l");
    EXPECT_EQ(p.name, "Model parameters");
    ASSERT_EQ(p.items.size(), 3u);
    EXPECT_TRUE(p.items[0].slider);
    EXPECT_EQ(p.items[0].define, "S0");
    EXPECT_EQ(p.items[0].label, "Segment length");
    EXPECT_DOUBLE_EQ(p.items[0].min, 0.5);  // 50 / 100
    EXPECT_DOUBLE_EQ(p.items[0].max, 1.5);
    EXPECT_DOUBLE_EQ(p.items[0].value, 1.0);
    EXPECT_FALSE(p.items[1].slider);
    EXPECT_EQ(p.items[1].define, "LEFT");
    EXPECT_DOUBLE_EQ(p.items[1].value, 1.0);
    ASSERT_EQ(p.problems.size(), 1u);
    EXPECT_EQ(p.problems[0], "panel.l:25: expected two numbers after 'min/max:', not 'zero 300'");
}

TEST(VlabPanel, TheSpecificationsSayWhichLsystemAPanelEdits) {
    namespace fs = std::filesystem;
    const fs::path folder = fs::path(testing::TempDir()) / ("vlab_panel_" + std::to_string(getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / "specifications") << "a.l\npanel.l\nL-system:\n\tpanel:\n\t\tpanel panel.l | awkped a.l\n"
                                                "animate:\n\tpanel panel.a | ped a.a\n";
    std::ofstream(folder / "panel.l") << kPanel;
    std::ofstream(folder / "panel.a") << kPanel;
    EXPECT_EQ(vlabPanelsOf(folder.string(), "a.l").size(), 1u);
    EXPECT_EQ(vlabPanelsOf(folder.string(), "b.l").size(), 0u);
    fs::remove_all(folder);
}

}  // namespace
