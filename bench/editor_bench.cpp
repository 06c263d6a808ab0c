// Typing in the grammar editor: one keystroke on a 2,000-line grammar, from the key to a
// highlighted frame of the editor widget (its text model edit, the highlighting, and the ImGui
// frame that lays the visible lines out into draw lists), all on the CPU with no window (ImGui
// runs headless here: the fonts are built, nothing is drawn to a screen). Bar: 5 ms. The
// baseline in the same run is an ImGui frame of the same editor with no keystroke.
//
//   build/bench/editor_bench
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "app/viewer/window/editor.hpp"

int main() {
    using namespace sprout::viewer::editor;
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(1440, 860);
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    // 2,000 lines: rules with contexts, conditions, parameters and probabilities, comments, settings.
    std::string text = "# a long grammar\nn: 6\nangle: 22.5\naxiom: A(1) [ +B(2) ] C\n";
    for (int i = 0; i < 1996; ++i)
        text += "B(x) < A" + std::to_string(i) + "(y, z) > C : y > x * 0.5 && z < " + std::to_string(i) +
                " -> F(y) [ +(22.5) A(y * 0.9, z + 1) ] /(137.5) ~l(0.3) : 0.5  # rule " + std::to_string(i) + "\n";
    Editor editor;
    editor.sync(text, true);
    editor.gotoLineCol(1000, 20);  // typing in the middle
    const std::vector<Marker> markers{{1000, 5, true, "an error to mark"}};
    const std::vector<std::string> completions{"angle:", "axiom:", "environment:", "sin", "cos"};
    auto frame = [&](bool key) {
        io.DeltaTime = 1.0f / 60;
        if (key) io.AddInputCharacter('x');
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(430, 860));
        ImGui::Begin("panel");
        editor.draw("grammar", 400, sprout::FileKind::Lsys, markers, completions);
        ImGui::End();
        ImGui::Render();
    };
    for (int i = 0; i < 5; ++i) frame(false);  // warm up
    double typed = 1e9, idle = 1e9;
    for (int i = 0; i < 20; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        frame(true);
        typed = std::min(typed, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        t0 = std::chrono::steady_clock::now();
        frame(false);
        idle = std::min(idle, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    const int lines = editor.model().lineCount();
    std::printf("editor_bench: %d lines (%zu KB): keystroke to highlighted frame %.2f ms of CPU (bar 5 ms, %.2fx of the bar); "
                "a frame without typing %.2f ms: ratio %.1f\n",
                lines, text.size() / 1024, typed, typed / 5.0, idle, typed / idle);
    ImGui::DestroyContext();
    return typed < 5.0 ? 0 : 1;
}
