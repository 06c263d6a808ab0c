// The panel drawn again only where it changed (app/viewer/window/window_present.hpp): the
// tiles whose triangles changed between two frames of ImGui, and the bands they make. ImGui
// runs here without a window or GL: its draw data is what the window's frames hand over.
#include <gtest/gtest.h>
#include <imgui.h>

#include <cstdint>
#include <string>
#include <vector>

#include "app/viewer/window/window_present.hpp"

using namespace sprout::viewer::detail;

namespace {

constexpr float kWidth = 430, kHeight = 600;

struct ImGuiRun {
    ImGuiRun() {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(kWidth, kHeight);
        io.IniFilename = nullptr;
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    }
    ~ImGuiRun() { ImGui::DestroyContext(); }
};

struct Panel {
    std::vector<std::uint64_t> tiles;
    int columns = 0;
    ImVec2 changedMin, changedMax;  // where the changing line was drawn
};

// A panel like the viewer's: a few lines, one of them `changing`, after `extraLines` lines
// added at its top.
Panel frame(const std::string& changing, int extraLines = 0) {
    ImGuiIO& io = ImGui::GetIO();
    io.DeltaTime = 1.0f / 60;
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(kWidth, kHeight));
    ImGui::Begin("panel", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
    for (int i = 0; i < extraLines; ++i) ImGui::Text("a line above, %d", i);
    ImGui::Text("Grammar");
    ImGui::Button("Cancel");
    for (int i = 0; i < 5; ++i) ImGui::Text("a line of the panel, %d", i);
    Panel p;
    ImGui::TextUnformatted(changing.c_str());
    p.changedMin = ImGui::GetItemRectMin(), p.changedMax = ImGui::GetItemRectMax();
    for (int i = 0; i < 12; ++i) ImGui::Text("another line below, %d", i);
    ImGui::End();
    ImGui::Render();
    p.tiles = panelTiles(ImGui::GetDrawData(), kWidth, kHeight, p.columns);
    return p;
}

}  // namespace

TEST(PanelTiles, TheSamePanelChangesNoTile) {
    ImGuiRun run;
    const Panel a = frame("deriving step 3"), b = frame("deriving step 3");
    ASSERT_EQ(a.columns, int(kWidth / kPanelTile) + 1);
    ASSERT_EQ(a.tiles.size(), b.tiles.size());
    EXPECT_TRUE(panelBands(a.tiles, b.tiles, a.columns).empty());
}

TEST(PanelTiles, AChangedLineIsTheOnlyBandDrawnAgain) {
    ImGuiRun run;
    const Panel a = frame("deriving step 3"), b = frame("deriving step 4");
    const auto bands = panelBands(a.tiles, b.tiles, a.columns);
    ASSERT_EQ(bands.size(), 1u);
    // It holds the line's glyphs that changed and reaches no further than the tiles they meet.
    EXPECT_LE(bands[0].y0, b.changedMin.y);
    EXPECT_GE(bands[0].y1, b.changedMax.y);
    EXPECT_LE(bands[0].y1 - bands[0].y0, 2 * kPanelTile);
    EXPECT_LT(bands[0].x1 - bands[0].x0, kWidth / 2) << "only the end of the line changed";
}

TEST(PanelTiles, ALineAddedAboveRedrawsEverythingBelowIt) {
    ImGuiRun run;
    const Panel a = frame("deriving step 3"), b = frame("deriving step 3", 1);
    const auto bands = panelBands(a.tiles, b.tiles, a.columns);
    ASSERT_FALSE(bands.empty());
    EXPECT_GE(bands.back().y1, b.changedMax.y) << "the lines moved down are drawn again";
    EXPECT_LE(bands.front().y0, b.changedMin.y);
}

TEST(PanelTiles, ManyChangesAreMergedIntoTheFewestNearestBands) {
    const int columns = 4;
    std::vector<std::uint64_t> before(size_t(columns) * 12, 1), after = before;
    for (int row : {1, 3, 4, 8, 10}) after[size_t(row) * columns + 2] = 2;  // runs: 1, 3-4, 8, 10
    after[size_t(4) * columns] = 2;
    auto bands = panelBands(before, after, columns, 8);
    ASSERT_EQ(bands.size(), 4u);
    EXPECT_EQ(bands[1].y0, 3 * kPanelTile);
    EXPECT_EQ(bands[1].y1, 5 * kPanelTile);
    EXPECT_EQ(bands[1].x0, 0) << "as wide as its rows' changes reach";
    EXPECT_EQ(bands[1].x1, 3 * kPanelTile);
    bands = panelBands(before, after, columns, 2);
    ASSERT_EQ(bands.size(), 2u);  // the nearest first: 1 with 3-4, then 8 with 10
    EXPECT_EQ(bands[0].y0, 1 * kPanelTile);
    EXPECT_EQ(bands[0].y1, 5 * kPanelTile);
    EXPECT_EQ(bands[1].y0, 8 * kPanelTile);
    EXPECT_EQ(bands[1].y1, 11 * kPanelTile);
}
