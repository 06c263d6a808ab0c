// The ImGui panel: grammar editor with errors, sliders, growth, view and light, presets,
// files and the statistics line.
#include <cstring>
#include <filesystem>
#include "app/render/gl.hpp"  // glad first: GLFW must not include GL/gl.h
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <glm/geometric.hpp>
#include <cstdio>
#include <sstream>
#include <vector>

#include "app/presets.hpp"
#include "app/viewer/app.hpp"
#include "app/viewer/editor/editor.hpp"
#include "app/viewer/text_edit.hpp"
#include "core/base/bounded.hpp"

namespace sprout::viewer {
namespace {

const ImVec4 kError(1.0f, 0.45f, 0.4f, 1), kWarning(1.0f, 0.8f, 0.35f, 1), kDim(0.65f, 0.65f, 0.65f, 1);

// A slider over a value written in the text; returns true when moved.
bool valueSlider(App& app, const char* label, const char* key, double current, float lo, float hi, const char* fmt = "%.3g") {
    float v = toFloat(current);
    if (ImGui::SliderFloat(label, &v, lo, hi, fmt)) {
        app.state.setDirectiveValue(key, v);
        return true;
    }
    return false;
}

// ImGui's built-in font has ASCII only: show the messages' dashes and quotes that way.
std::string ascii(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s.compare(i, 3, "\xE2\x80\x94") == 0) {
            out += "--";
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

// Byte offset of (line, col) in `text`, columns counted in characters.
int offsetOf(const std::string& text, int line, int col) {
    size_t pos = 0;
    for (int l = 1; l < line && pos < text.size(); ++l) {
        size_t nl = text.find('\n', pos);
        if (nl == std::string::npos) return int(text.size());
        pos = nl + 1;
    }
    for (int c = 1; c < col && pos < text.size() && text[pos] != '\n'; ++c) {
        ++pos;
        while (pos < text.size() && (static_cast<unsigned char>(text[pos]) & 0xC0) == 0x80) ++pos;
    }
    return int(pos);
}

// Words the editor completes: settings, functions, and the grammar's longer module names.
std::vector<std::string> completionsFor(App& app) {
    static const char* fixed[] = {"angle:", "axiom:", "iterations:", "step:", "width:", "seed:", "tropism:", "palette:",
                                  "gradient:", "view:", "define:", "module:", "ignore:", "consider:", "environment:",
                                  "branch_scale:", "step_scale:", "sphere", "ellipsoid", "cylinder", "obstacle", "ground",
                                  "light", "attraction", "influence", "sin", "cos", "tan", "sqrt", "floor", "ceil", "min", "max",
                                  "ran", "nran", "random", "trunc", "fabs", "exp", "log", "pow", "atan2", "Lsystem:",
                                  "derivation length:", "Axiom:", "decomposition", "homomorphism", "endlsystem",
                                  "maximum depth:", "#define", "#include"};
    std::vector<std::string> out(std::begin(fixed), std::end(fixed));
    if (auto plant = app.state.plant(); plant && plant->grammar)
        for (size_t k = 0; k < plant->grammar->alphabet.size(); ++k) {
            const std::string& name = plant->grammar->alphabet[SymbolId(k)].name;
            if (name.size() >= 3 && std::isalpha(static_cast<unsigned char>(name[0]))) out.push_back(name);
        }
    return out;
}

void grammarSection(App& app) {
    // The editor follows the text the rest of the viewer changes (sliders, a file opened).
    const std::string document = app.state.title() + "|" + app.state.path().string();
    // Another file or preset is a new document (a new undo history); Save as keeps the text.
    const bool newDocument = document != app.editorDocument && app.state.text() != app.editor.text();
    app.editorDocument = document;
    app.editor.sync(app.state.text(), newDocument);
    if (app.jumpTo >= 0) {  // a clicked message or rule: the cursor goes there
        const editor::Pos p = app.editor.model().posOf(std::size_t(app.jumpTo));
        app.editor.gotoLineCol(p.line + 1, p.col + 1);
        app.jumpTo = -1;
    }
    std::vector<editor::Marker> markers;
    if (auto latest = app.state.latest())
        for (const auto& d : latest->diagnostics) markers.push_back({d.line, d.col, d.severity == Severity::Error, ascii(d.message)});
    const float h = std::max(160.0f, ImGui::GetTextLineHeight() * 16);
    FileKind kind = app.state.kind();
    if (kind == FileKind::Png) kind = FileKind::Lsys;
    app.editor.setBandLine(app.highlightLine);
    if (app.completionsOf != app.state.plant() || app.completions.empty()) {
        app.completions = completionsFor(app);
        app.completionsOf = app.state.plant();
    }
    if (app.editor.draw("grammar", h, kind, markers, app.completions)) app.state.setText(app.editor.text());
    auto latest = app.state.latest();
    if (latest) {
        // Each problem at its line:col; a click puts the editor's cursor there.
        for (const auto& d : latest->diagnostics) {
            ImGui::PushStyleColor(ImGuiCol_Text, d.severity == Severity::Error ? kError : kWarning);
            char label[64];
            std::snprintf(label, sizeof label, "line %d, col %d##%d_%d", d.line, d.col, d.line, d.col);
            if (ImGui::SmallButton(label)) {
                app.jumpTo = offsetOf(app.state.text(), d.line, d.col);
            }
            ImGui::SameLine();
            ImGui::TextWrapped("%s%s", d.severity == Severity::Warning ? "warning: " : "", ascii(d.message).c_str());
            ImGui::PopStyleColor();
        }
        if (hasErrors(latest->diagnostics) && app.state.plant())
        {
            ImGui::PushStyleColor(ImGuiCol_Text, kDim);
            ImGui::TextWrapped("(the last good plant stays on screen until the text is fixed)");
            ImGui::PopStyleColor();
        }
        if (!latest->message.empty() && !latest->cancelled) {
            ImGui::PushStyleColor(ImGuiCol_Text, kError);
            ImGui::TextWrapped("%s", latest->message.c_str());
            ImGui::PopStyleColor();
        }
    }
    const Worker& w = app.state.worker();
    if (w.busy()) {
        char label[64];
        std::snprintf(label, sizeof label, "deriving step %d", w.progressStep());
        ImGui::ProgressBar(w.progress(), ImVec2(-90, 0), label);
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) app.state.worker().cancel();
    }
}

// An iterated function system: one row of seven numbers per map (a b c d e f p), dragged
// like sliders and written back into the text.
void ifsMaps(App& app) {
    const std::string& text = app.state.text();
    std::vector<std::string> lines;
    {
        size_t pos = 0;
        while (pos <= text.size()) {
            size_t end = text.find('\n', pos);
            if (end == std::string::npos) end = text.size();
            lines.push_back(text.substr(pos, end - pos));
            pos = end + 1;
        }
    }
    ImGui::TextColored(kDim, "maps: a b c d e f p  (x' = a x + b y + e, y' = c x + d y + f)");
    int index = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
        std::string body = lines[i].substr(0, lines[i].find('#'));
        std::istringstream in(body);
        double v[7];
        int n = 0;
        while (n < 7 && (in >> v[n])) ++n;
        std::string extra;
        if (n != 7 || (in >> extra)) continue;
        ImGui::PushID(int(i));
        ImGui::SetNextItemWidth(-40);
        if (ImGui::DragScalarN("##map", ImGuiDataType_Double, v, 7, 0.002f, nullptr, nullptr, "%.3f")) {
            std::string line;
            for (int k = 0; k < 7; ++k) line += (k ? "  " : "  ") + formatValue(v[k]);
            lines[i] = line;
            std::string out;
            for (size_t j = 0; j < lines.size(); ++j) out += lines[j] + (j + 1 < lines.size() ? "\n" : "");
            app.state.setText(out);
        }
        ImGui::SameLine();
        ImGui::Text("w%d", ++index);
        ImGui::PopID();
    }
}

void parameterSection(App& app) {
    auto plant = app.state.plant();
    if (plant && plant->image) {
        ifsMaps(app);
        return;
    }
    if (!plant || !plant->grammar) return;
    const Settings& s = plant->grammar->settings;
    int n = plant->iterations;
    if (ImGui::SliderInt("n (iterations)", &n, 0, std::max(12, plant->iterations + 2))) app.state.setIterations(n);
    valueSlider(app, "angle", "angle", s.angle.mean, 0, 180, "%.1f deg");
    valueSlider(app, "step", "step", s.step.mean, 0.01f, std::max(10.0f, float(s.step.mean) * 2));
    valueSlider(app, "width", "width", s.width, 0, std::max(2.0f, float(s.width) * 2), s.width <= 0 ? "auto" : "%.3g");
    valueSlider(app, "branch scale", "branch_scale", s.branchLength, 0.1f, 1.5f);
    if (s.tropismStrength != 0 || ImGui::TreeNode("tropism")) {
        float e = float(s.tropismStrength);
        if (ImGui::SliderFloat("tropism e", &e, -1, 1, "%.3f")) {
            char buf[96];
            std::snprintf(buf, sizeof buf, "%s %s %s %s", formatValue(s.tropism[0]).c_str(), formatValue(s.tropism[1]).c_str(),
                          formatValue(s.tropism[2]).c_str(), formatValue(e).c_str());
            app.state.setText(setDirective(app.state.text(), "tropism", s.tropism == std::array<double, 3>{0, 0, 0} ? "0 -1 0 " + formatValue(e) : buf));
        }
        if (s.tropismStrength == 0) ImGui::TreePop();
    }
    int seed = int(plant->seed % 1000000000ull);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.45f);
    if (ImGui::InputInt("seed", &seed)) app.state.setSeed(std::uint64_t(std::max(0, seed)));
    ImGui::SameLine();
    if (ImGui::Button("New specimen (N)")) app.state.newSpecimen();
    // One slider per `define`, generated from the file (L-Py's scalar parameters panel).
    for (const auto& name : plant->grammar->defineOrder) {
        double v = plant->grammar->defines.at(name);
        float f = toFloat(v);
        float span = std::max(1.0f, std::fabs(f) * 2);
        if (ImGui::SliderFloat(name.c_str(), &f, v < 0 ? -span : 0.0f, span, "%.3g")) app.state.setDefineValue(name, f);
    }
}

void growthSection(App& app) {
    auto plant = app.state.plant();
    if (!plant) return;
    int step = plant->displayStep;
    if (ImGui::SliderInt("step", &step, 0, plant->iterations)) app.state.setDisplayStep(step);
    if (ImGui::Button("|<")) app.state.setDisplayStep(0);
    ImGui::SameLine();
    if (ImGui::Button("<")) app.state.stepBy(-1);
    ImGui::SameLine();
    if (ImGui::Button(app.state.playing() ? "Pause" : "Play")) app.state.setPlaying(!app.state.playing());
    ImGui::SameLine();
    if (ImGui::Button(">")) app.state.stepBy(1);
    ImGui::SameLine();
    if (ImGui::Button(">|")) app.state.setDisplayStep(plant->iterations);
    ImGui::SameLine();
    ImGui::Checkbox("loop", &app.state.loop);
    ImGui::SliderFloat("steps / s", &app.state.stepsPerSecond, 0.25f, 10, "%.2f");
    ImGui::Checkbox("smooth growth (new segments grow in)", &app.state.smoothGrowth);
    if (ImGui::Button(app.videoJob.running() ? "Recording..." : "Record video...") && !app.videoJob.running()) app.videoPopup = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the growth from the axiom to step n, or a 360-degree turntable, as MP4");
}

// The environment of an open L-system: drawn or not, a slice of its light, and one slider per
// number of its `environment:` lines, written back into the text (the plant regrows on the
// worker as for any edit).
void environmentSection(App& app, const Environment& env) {
    ViewSettings& v = app.view;
    if (ImGui::Checkbox("show environment", &v.showEnvironment)) app.environmentDirty = true;
    if (env.isLight()) {
        ImGui::SameLine();
        if (ImGui::Checkbox("light slice", &v.lightSlice)) app.environmentDirty = true;
        if (v.lightSlice && ImGui::SliderFloat("slice height", &v.sliceHeight, 0, 1, "%.2f")) app.environmentDirty = true;
    }
    auto plant = app.state.plant();
    const float scale = plant && plant->geometry && !plant->geometry->bounds.empty
                            ? std::max(1.0f, glm::length(plant->geometry->bounds.size()))
                            : 10.0f;
    const std::string& text = app.state.text();
    int id = 0;
    for (const EnvironmentNumber& n : environmentNumbers(text)) {
        ImGui::PushID(id++);
        float f = toFloat(n.value);
        bool moved = false;
        using Kind = EnvironmentNumber::Kind;
        switch (n.kind) {
            case Kind::Position: moved = ImGui::DragFloat(n.label.c_str(), &f, scale * 0.002f, 0, 0, "%.3g"); break;
            case Kind::Size: moved = ImGui::DragFloat(n.label.c_str(), &f, std::max(0.001f, f * 0.005f), 0.01f, 1e6f, "%.3g"); break;
            case Kind::Shadow: moved = ImGui::SliderFloat(n.label.c_str(), &f, 0.01f, 2, "%.2f"); break;
            case Kind::Azimuth: moved = ImGui::SliderFloat(n.label.c_str(), &f, -180, 180, "%.0f deg"); break;
            case Kind::Elevation: moved = ImGui::SliderFloat(n.label.c_str(), &f, 1, 90, "%.0f deg"); break;
            case Kind::Count: {
                int k = saturate<int>(f);
                moved = ImGui::DragInt(n.label.c_str(), &k, std::max(1.0f, float(k) * 0.005f), 1, 1000000);
                f = float(k);
                break;
            }
        }
        if (moved) app.state.setText(setEnvironmentNumber(text, n, f));
        ImGui::PopID();
        if (moved) break;  // the text changed under the others
    }
}

// The text of one line of the grammar (1-based), trimmed.
std::string lineText(const std::string& text, int line) {
    size_t pos = 0;
    for (int l = 1; l < line && pos != std::string::npos; ++l) {
        pos = text.find('\n', pos);
        if (pos != std::string::npos) ++pos;
    }
    if (pos == std::string::npos || pos >= text.size()) return "";
    std::string out = text.substr(pos, text.find('\n', pos) - pos);
    while (!out.empty() && (out.back() == '\r' || out.back() == ' ')) out.pop_back();
    return out;
}

// Which rule made this branch: the picked module, its rule and ancestors; the rule under the
// editor's cursor, and how much it made.
void whySection(App& app) {
    auto plant = app.state.plant();
    if (!plant || !plant->geometry) return;
    if (plant->forest) {  // a forest: which plant, which species
        if (!app.selection || app.selection->forestPlant < 0 || app.selection->plant != plant) {
            ImGui::TextWrapped("Click a plant in the view to see which one it is and its species.");
            return;
        }
        const ForestPlant& f = (*plant->forest)[size_t(app.selection->forestPlant)];
        ImGui::Text("plant %d of %zu: %s%s", app.selection->forestPlant + 1, plant->forest->size(), f.species.c_str(),
                    f.grass ? " (grass)" : "");
        ImGui::Text("at (%.1f, %.1f), turned %.0f deg; %s %u of its %u", double(f.at.x), double(f.at.z), double(f.yaw),
                    app.selection->surface ? "surface" : "segment", app.selection->module,
                    app.selection->surface ? f.surfaces : f.segments);
        ImGui::TextDisabled("open the species (Presets or File) to see which rule made it");
        return;
    }
    if (!plant->grammar) return;
    if (!app.state.picking()) {
        ImGui::TextWrapped("Click a stem or leaf in the view to see which module drew it and which rule made it.");
        if (ImGui::Button("Start picking")) app.state.setPicking(true);
        return;
    }
    const std::string& text = app.state.text();
    // The rule under the cursor: everything it made lights up (when the cursor comes to it).
    if (const int line = app.editor.model().cursor().line + 1; app.followCursor && line != app.cursorLine) {
        app.cursorLine = line;
        bool isRule = false;
        for (const Production& p : plant->grammar->rules.productions) isRule |= p.line == line;
        for (const Production& p : plant->grammar->decomposition.productions) isRule |= p.line == line;
        if (isRule) app.setHighlightLine(line);
    }
    ImGui::Checkbox("highlight what the rule under the cursor made", &app.followCursor);
    if (app.highlightLine > 0) {
        ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.25f, 1), "line %d made %zu stems and leaves:", app.highlightLine, app.highlightCount);
        ImGui::TextWrapped("%s", ascii(lineText(text, app.highlightLine)).c_str());
        if (ImGui::SmallButton("clear highlight")) app.setHighlightLine(0);
    }
    ImGui::Separator();
    if (!app.selection) {
        ImGui::TextWrapped("Click a stem or leaf in the view.");
        return;
    }
    const App::Selection& sel = *app.selection;
    const PickData& pick = *sel.plant->pick;
    const Grammar& g = *pick.record.grammar;
    const auto& drawn = pick.record.steps[size_t(pick.step)];
    if (pick.homomorphism) {
        ImGui::TextWrapped("%s, module %u of the string the interpretation rules drew (their modules have no lineage).",
                           sel.surface ? "a leaf" : "a stem", sel.module);
        return;
    }
    if (!drawn || sel.module >= drawn->size()) return;
    ImGui::Text("%s %s, module %u of step %d", sel.surface ? "leaf / surface" : "stem", sel.text.c_str(),
                sel.module, pick.step);
    for (size_t k = 0; k < sel.links.size(); ++k) {
        const LineageLink& l = sel.links[k];
        ImGui::PushID(int(k));
        const std::string name = g.alphabet[l.symbol].name;
        if (l.ruleLine > 0) {
            if (ImGui::SmallButton(("line " + std::to_string(l.ruleLine)).c_str())) {
                app.jumpTo = offsetOf(text, l.ruleLine, 1);
                app.setHighlightLine(l.ruleLine);
            }
            ImGui::SameLine();
            ImGui::TextWrapped("%s%s made at step %d by: %s", k ? "<- " : "", name.c_str(), l.step, ascii(lineText(text, l.ruleLine)).c_str());
        } else {
            ImGui::TextWrapped("%s%s, module %u of the axiom", k ? "<- " : "", name.c_str(), l.index);
        }
        ImGui::PopID();
    }
}

void viewSection(App& app) {
    ViewSettings& v = app.view;
    if (ImGui::Button("Frame (F)")) app.frame();
    ImGui::SameLine();
    if (ImGui::Button("Reset (R)")) app.resetView();
    ImGui::SameLine();
    ImGui::Checkbox("turntable (T)", &v.turntable);
    bool changed = false;
    changed |= ImGui::SliderFloat("sun azimuth", &v.sunAzimuth, -180, 180, "%.0f deg");
    changed |= ImGui::SliderFloat("sun elevation", &v.sunElevation, 5, 90, "%.0f deg");
    if (changed) app.applySun();
    if (ImGui::SliderFloat("sun intensity", &v.render.sunIntensity, 0, 2, "%.2f")) app.needsRedraw = true;
    if (ImGui::Checkbox("shadows", &v.render.shadows)) app.needsRedraw = true;
    ImGui::SameLine();
    if (ImGui::Checkbox("ground", &v.render.ground)) app.needsRedraw = true;
    if (ImGui::ColorEdit3("sky", &v.render.backgroundTop.x, ImGuiColorEditFlags_NoInputs)) app.needsRedraw = true;
    ImGui::SameLine();
    if (ImGui::ColorEdit3("horizon", &v.render.backgroundBottom.x, ImGuiColorEditFlags_NoInputs)) app.needsRedraw = true;
    ImGui::SetNextItemWidth(140);
    if (ImGui::BeginCombo("##shotsize", kScreenshotSizes[v.screenshotSize].label)) {
        for (int i = 0; i < int(std::size(kScreenshotSizes)); ++i)
            if (ImGui::Selectable(kScreenshotSizes[i].label, i == v.screenshotSize)) v.screenshotSize = i;
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::Button("Screenshot (P)")) {
        const auto& s = kScreenshotSizes[v.screenshotSize];
        app.takeScreenshot(app.nextScreenshotPath(), s.width, s.height);
    }
}

void presetSection(App& app) {
    auto names = presetNames();
    for (const auto& n : ifsPresetNames()) names.push_back(n);
    for (const auto& n : scenePresetNames()) names.push_back(n);
    const float cell = 96;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float itemWidth = cell + 2 * style.FramePadding.x + style.ItemSpacing.x;
    int columns = std::max(1, int((ImGui::GetContentRegionAvail().x + style.ItemSpacing.x) / itemWidth));
    int i = 0;
    for (const auto& name : names) {
        ImGui::PushID(name.c_str());
        ImGui::BeginGroup();
        const Image* img = app.thumbnails.get(name);
        bool clicked = false;
        if (img) {
            unsigned& tex = app.thumbnails.textures[name];
            if (!tex) {
                glGenTextures(1, &tex);
                glBindTexture(GL_TEXTURE_2D, tex);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
                glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
                glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img->width, img->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, img->rgba.data());
            }
            clicked = ImGui::ImageButton(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(tex)), ImVec2(cell, cell * 0.75f));
        } else {
            clicked = ImGui::Button("...", ImVec2(cell + 6, cell * 0.75f + 6));
        }
        ImGui::TextColored(kDim, "%.14s", name.c_str());
        ImGui::EndGroup();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", name.c_str());
        if (clicked) {
            if (app.state.dirty()) app.state.autosave(true);  // never lose the edits
            app.state.openText(std::string(*presetText(name)), {}, name);
            app.frameOnNextPlant = true;
            app.say("opened preset " + name);
        }
        ImGui::PopID();
        if (++i % columns != 0) ImGui::SameLine();
    }
    if (i % columns != 0) ImGui::NewLine();
}

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
    ImGui::Begin("Sprout", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_MenuBar |
                     ImGuiWindowFlags_NoTitleBar);
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
    if (ImGui::CollapsingHeader("Grammar", ImGuiTreeNodeFlags_DefaultOpen)) grammarSection(app);
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) parameterSection(app);
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
        // The frame's time is read twice a second: a number that changes every frame would
        // make every frame one to show (the window skips frames in which nothing changes).
        static double shownFrameMs = 0, shownAt = -1;
        if (glfwGetTime() - shownAt > 0.5) shownFrameMs = app.frameMs, shownAt = glfwGetTime();
        ImGui::TextColored(kDim, "derive %.1f ms, interpret %.1f ms, upload %.1f ms, draw %.1f ms, frame %.1f ms",
                           p->deriveMs, p->interpretMs, app.uploadMs, app.drawMs, shownFrameMs);
    }
    if (!app.status.empty() && glfwGetTime() - app.statusTime < 6) ImGui::TextWrapped("%s", app.status.c_str());
    ImGui::End();
    helpWindow(app);
}

}  // namespace sprout::viewer
