// The ImGui panel: its window with the File menu and popups, the sections in order (drawn by
// panel_grammar.cpp, panel_sections.cpp, inspector.cpp), the statistics line, the help window.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>

#include "app/viewer/window/app.hpp"
#include "app/viewer/window/panel_sections.hpp"

namespace sprout::viewer {

using namespace detail;  // the sections and colours (panel_sections.hpp)

namespace {

void fileMenu(App& app) {
    if (ImGui::BeginMenuBar()) {
        if (ImGui::BeginMenu("File")) {
            if (ImGui::MenuItem("Open...", "Ctrl+O")) app.openPopup = true;
            if (ImGui::MenuItem("Save", "Ctrl+S")) app.save();
            if (ImGui::MenuItem("Save as...")) app.saveAsPopup = true;
            if (ImGui::MenuItem("Export model...", "Ctrl+E", false, !app.exportJob.running())) app.exportPopup = true;
            if (ImGui::MenuItem("Record video...", nullptr, false, !app.videoJob.running())) app.videoPopup = true;
            if (ImGui::MenuItem("Quit", "Ctrl+Q")) app.quitRequested = true;
            ImGui::EndMenu();
        }
        if (ImGui::BeginMenu("Help")) {
            if (ImGui::MenuItem("Keyboard shortcuts", "F1")) app.showHelp = true;
            ImGui::EndMenu();
        }
        ImGui::EndMenuBar();
    }
    auto pathPopup = [&](bool& flag, const char* title, const char* action, auto&& run, const char* extension = ".lsys",
                         const char* help = nullptr) {
        if (flag) {
            ImGui::OpenPopup(title);
            std::filesystem::path p = app.state.path().empty() ? std::filesystem::path("plant.lsys") : app.state.path();
            app.pathInput = p.replace_extension(extension).string();
            flag = false;
        }
        if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
            if (help) ImGui::TextUnformatted(help);
            ImGui::SetNextItemWidth(360);
            bool enter = ImGui::InputText("path", &app.pathInput, ImGuiInputTextFlags_EnterReturnsTrue);
            if (ImGui::Button(action) || enter) {
                run(app.pathInput);
                ImGui::CloseCurrentPopup();
            }
            ImGui::SameLine();
            if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
            ImGui::EndPopup();
        }
    };
    pathPopup(app.openPopup, "Open grammar", "Open", [&](const std::string& p) { app.openFile(p); });
    pathPopup(app.saveAsPopup, "Save grammar as", "Save", [&](const std::string& p) {
        std::string e;
        app.say(app.state.saveAs(p, e) ? "saved " + p : e);
    });
    pathPopup(
        app.exportPopup, "Export model", "Export", [&](const std::string& p) { app.exportModel(p); }, ".glb",
        "The format follows the extension: .glb (glTF: Blender, game engines), .obj (+ .mtl),\n"
        ".ply (vertex colours) or .svg (a 2D drawing, for planar systems and papers).");
    if (app.videoPopup) {
        ImGui::OpenPopup("Record video");
        std::filesystem::path p = app.state.path().empty() ? std::filesystem::path("plant") : app.state.path();
        app.pathInput = p.replace_extension().string() + (app.videoKind == 0 ? "-growth.mp4" : "-turntable.mp4");
        app.videoPopup = false;
    }
    if (ImGui::BeginPopupModal("Record video", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const int before = app.videoKind;
        ImGui::RadioButton("growth: axiom to step n, half a second per step", &app.videoKind, 0);
        ImGui::RadioButton("turntable: 360 degrees in 5 seconds", &app.videoKind, 1);
        if (before != app.videoKind) {  // follow the kind in the suggested name
            const char* from = before == 0 ? "-growth.mp4" : "-turntable.mp4";
            const char* to = app.videoKind == 0 ? "-growth.mp4" : "-turntable.mp4";
            if (app.pathInput.ends_with(from)) app.pathInput = app.pathInput.substr(0, app.pathInput.size() - std::strlen(from)) + to;
        }
        ImGui::TextUnformatted("1280 x 720, 24 frames/s; .mp4 needs ffmpeg, otherwise or with .png: numbered PNG frames");
        ImGui::SetNextItemWidth(360);
        bool enter = ImGui::InputText("path", &app.pathInput, ImGuiInputTextFlags_EnterReturnsTrue);
        if (ImGui::Button("Record") || enter) {
            app.recordVideo(app.videoKind == 0 ? "growth" : "turntable", app.pathInput);
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    if (app.videoJob.running()) {
        char buf[64];
        std::snprintf(buf, sizeof buf, " (%.0f s)", app.videoJob.seconds());
        ImGui::TextUnformatted(("recording " + app.videoJob.path() + buf).c_str());
    }
    if (std::string m = app.videoJob.poll(); !m.empty()) app.say(m);
    // A running export: its progress, and its result when it ends.
    if (app.exportJob.running()) {
        ImGui::ProgressBar(float(app.exportJob.progress()), ImVec2(-1, 0), ("exporting " + app.exportJob.path()).c_str());
        app.needsRedraw = true;
    } else if (std::string m = app.exportJob.takeMessage(); !m.empty()) {
        app.say(m);
    }
    if (app.quitPopup) {
        ImGui::OpenPopup("Unsaved changes");
        app.quitPopup = false;
    }
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted("The grammar has unsaved changes.");
        if (ImGui::Button("Save and quit")) {
            std::string e;
            if (app.state.path().empty()) app.saveAsPopup = true;
            else if (app.state.save(e)) app.quitConfirmed = true;
            else app.say(e);
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Quit without saving")) {
            app.quitConfirmed = true;  // the text stays in the autosave file
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
}

void helpWindow(App& app) {
    if (!app.showHelp) return;
    ImGui::SetNextWindowSize(ImVec2(420, 0), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Keyboard shortcuts", &app.showHelp)) {
        const char* rows[][2] = {
            {"F1", "this help"},           {"F", "frame the plant"},        {"R", "reset the view"},
            {"T", "turntable on / off"},   {"Space", "play / pause growth"}, {"Left / Right", "previous / next step"},
            {"Up / Down", "one more / one fewer iteration"}, {"N", "new specimen (another seed)"},
            {"P", "screenshot"},           {"Ctrl+S", "save"},              {"Ctrl+O", "open"}, {"Ctrl+E", "export model"},
            {"A / D", "orbit left / right"}, {"W / S", "tilt up / down"},   {"Q / E", "zoom out / in"},
            {"Ctrl+Q", "quit"},            {"left drag", "orbit"},          {"right / middle drag", "pan"},
            {"wheel", "zoom"},
        };
        if (ImGui::BeginTable("keys", 2)) {
            for (auto& r : rows) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(r[0]);
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(r[1]);
            }
            ImGui::EndTable();
        }
    }
    ImGui::End();
}

}  // namespace

void drawPanel(App& app) {
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(app.window, &fw, &fh);
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(float(app.panelWidth), float(fh)));
    // No border: the panel ends at its strip's edge (a border's line is a pixel past it), so
    // the window can copy the strip when nothing in it changed.
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    ImGui::Begin("Sprout", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_MenuBar |
                     ImGuiWindowFlags_NoTitleBar);
    ImGui::PopStyleVar();
    fileMenu(app);
    const std::string title = app.state.title();
    ImGui::Text("%s%s", title.c_str(), app.state.dirty() ? " *" : "");
    if (!app.state.importedFrom().empty()) {
        ImGui::SameLine();
        ImGui::TextColored(kDim, "(imported from %s; Save as writes .lsys)", app.state.importedFrom().filename().string().c_str());
        // A Fractint file holds many systems: choose one.
        const auto& systems = app.state.importSystems();
        if (!systems.empty()) {
            static int current = 0;
            current = std::clamp(current, 0, int(systems.size()) - 1);
            if (ImGui::BeginCombo("system", systems[size_t(current)].c_str())) {
                for (int i = 0; i < int(systems.size()); ++i) {
                    if (ImGui::Selectable(systems[size_t(i)].c_str(), i == current)) {
                        current = i;
                        std::string e;
                        auto from = app.state.importedFrom();
                        if (app.state.open(from, e, systems[size_t(i)])) app.frameOnNextPlant = true;
                        else app.say(e);
                    }
                }
                ImGui::EndCombo();
            }
        }
    }
    if (const auto& object = app.state.vlabObject())
        if (ImGui::CollapsingHeader("VLab object", ImGuiTreeNodeFlags_DefaultOpen)) vlabSection(app, *object);
    if (ImGui::CollapsingHeader("Grammar", ImGuiTreeNodeFlags_DefaultOpen)) grammarSection(app);
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) parameterSection(app);
    if (app.state.kind() == FileKind::Lpy && hasLpyCurves(app))
        if (ImGui::CollapsingHeader("Curves", ImGuiTreeNodeFlags_DefaultOpen)) curveSection(app);
    if (app.state.kind() == FileKind::Lsys && hasLsysCurves(app))
        if (ImGui::CollapsingHeader("Functions and contours", ImGuiTreeNodeFlags_DefaultOpen)) lsysCurveSection(app);
    if (app.state.kind() == FileKind::Lpy && hasLpyMaterials(app))
        if (ImGui::CollapsingHeader("Materials", ImGuiTreeNodeFlags_DefaultOpen)) materialSection(app);
    if (app.state.vlabObject() && hasVlabCurves(app))
        if (ImGui::CollapsingHeader("Functions and contours", ImGuiTreeNodeFlags_DefaultOpen)) vlabCurveSection(app);
    if ((app.state.kind() == FileKind::Lpy || app.state.vlabObject()) && hasSurfaces(app))
        if (ImGui::CollapsingHeader("Surfaces", ImGuiTreeNodeFlags_DefaultOpen)) surfaceSection(app);
    if (app.state.vlabObject() && hasVlabColours(app))
        if (ImGui::CollapsingHeader("Colours", ImGuiTreeNodeFlags_DefaultOpen)) vlabColourSection(app);
    if (ImGui::CollapsingHeader("Growth", ImGuiTreeNodeFlags_DefaultOpen)) growthSection(app);
    if (auto plant = app.state.plant(); plant && plant->environment && !plant->environment->empty())
        if (ImGui::CollapsingHeader("Environment", ImGuiTreeNodeFlags_DefaultOpen)) environmentSection(app, *plant->environment);
    if (ImGui::CollapsingHeader("Why this branch?", app.state.picking() ? ImGuiTreeNodeFlags_DefaultOpen : 0)) whySection(app);
    if (app.openInspector) ImGui::SetNextItemOpen(true), app.openInspector = false;
    if (ImGui::CollapsingHeader("Derivation inspector")) inspectorSection(app);
    if (ImGui::CollapsingHeader("View and light")) viewSection(app);
    if (ImGui::CollapsingHeader("Presets", ImGuiTreeNodeFlags_DefaultOpen)) presetSection(app);
    // Statistics line.
    ImGui::Separator();
    auto p = app.state.plant();
    if (p && p->image) {
        ImGui::TextColored(kDim, "%s points of the chaos game in %.0f ms", withThousands(p->modules).c_str(), p->deriveMs);
    } else if (p && p->geometry) {
        static std::weak_ptr<const Result> countedOf;  // leaves counted once per plant, not every frame
        static std::size_t leaves = 0;
        if (countedOf.lock() != p) {
            countedOf = p;
            leaves = 0;
            for (const auto& s : p->geometry->surfaces) leaves += s.kind == SurfaceKind::Leaf;
        }
        ImGui::TextColored(kDim, "%s modules, %zu segments, %zu leaves, %zu polygons", withThousands(p->modules).c_str(),
                           p->geometry->cylinders.size(), leaves, p->geometry->polygons.indices.size() / 3);
        // The frame's and the view's times are read twice a second, and not while the view
        // moves: a number that changes every frame would make every frame one to show (the
        // window skips frames in which nothing changes) and one whose panel is drawn anew
        // (the window copies an unchanged panel).
        static double shownFrameMs = 0, shownDrawMs = 0, shownAt = -1;
        if (glfwGetTime() - shownAt > 0.5 && !app.interacting && !app.state.playing())
            shownFrameMs = app.frameMs, shownDrawMs = app.drawMs, shownAt = glfwGetTime();
        ImGui::TextColored(kDim, "derive %.1f ms, interpret %.1f ms, upload %.1f ms, draw %.1f ms, frame %.1f ms",
                           p->deriveMs, p->interpretMs, app.uploadMs, shownDrawMs, shownFrameMs);
    }
    if (!app.status.empty() && glfwGetTime() - app.statusTime < 6) ImGui::TextWrapped("%s", app.status.c_str());
    ImGui::End();
    helpWindow(app);
}

}  // namespace sprout::viewer
