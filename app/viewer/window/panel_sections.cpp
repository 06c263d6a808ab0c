// The panel's sections of settings: parameters (an IFS's maps), growth, the environment,
// view and light, and the presets with their thumbnails.
#include "app/render/gl.hpp"
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>
#include <glm/geometric.hpp>

#include "app/plant/presets.hpp"
#include "app/viewer/window/app.hpp"
#include "app/viewer/window/panel_sections.hpp"
#include "app/plant/lpy_scalars.hpp"
#include "app/plant/text_edit.hpp"
#include "core/base/bounded.hpp"

namespace sprout::viewer::detail {
namespace {

// A slider over a value written in the text; returns true when moved.
bool valueSlider(App& app, const char* label, const char* key, double current, float lo, float hi, const char* fmt = "%.3g") {
    float v = toFloat(current);
    if (ImGui::SliderFloat(label, &v, lo, hi, fmt)) {
        app.state.setDirectiveValue(key, v);
        return true;
    }
    return false;
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

}  // namespace

// A scalar's right-click menu: renamed or deleted in the model's list, as L-Py Studio's editor
// does (one undo step each).
static void scalarMenu(App& app, const LpyScalar& s) {
    if (!ImGui::BeginPopupContextItem("scalar")) return;
    static char name[64];
    if (ImGui::IsWindowAppearing()) std::snprintf(name, sizeof name, "%s", s.name.c_str());
    ImGui::InputText("name", name, sizeof name);
    std::string error, text;
    if (ImGui::Button("rename")) {
        text = renameLpyScalar(app.state.text(), s.name, name, error);
        if (text.empty()) app.say(error);
        else app.state.setText(text, newGesture()), ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("delete")) {
        text = removeLpyScalar(app.state.text(), s.name, error);
        if (text.empty()) app.say(error);
        else app.state.setText(text, newGesture()), ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

// A new scalar: its name, kind and range, added to the model's list (made when it has none).
static void newScalar(App& app) {
    if (!ImGui::TreeNode("new scalar")) return;
    static char name[64] = "";
    static int kind = 1;
    static float range[3] = {0.5f, 0, 1};  // value, min, max
    ImGui::InputText("name##new", name, sizeof name);
    ImGui::Combo("kind", &kind, "Integer\0Float\0Bool\0Category\0");
    if (kind < 2) ImGui::InputFloat3("value, min, max", range, "%.3g");
    if (kind == 3) ImGui::TextColored(kDim, "a heading: the scalars added after it are its own");
    if (ImGui::Button("add")) {
        LpyScalar s;
        s.name = name;
        constexpr LpyScalar::Kind kinds[] = {LpyScalar::Kind::Integer, LpyScalar::Kind::Float, LpyScalar::Kind::Bool, LpyScalar::Kind::Category};
        s.kind = kinds[std::clamp(kind, 0, 3)];
        s.value = range[0], s.min = std::min(range[1], range[2]), s.max = std::max(range[1], range[2]);
        std::string error;
        const std::string text = addLpyScalar(app.state.text(), s, error);
        if (text.empty()) app.say(error);
        else app.state.setText(text, newGesture()), name[0] = 0;
    }
    ImGui::TextColored(kDim, "right-click a scalar to rename or delete it");
    ImGui::TreePop();
}

// An L-Py model's parameters: its derivation length and the scalars of its INITIALISATION
// part (L-Py's own parameter panel), each written back where the file sets it. The turtle's
// settings are Python's there, not lines Sprout may add.
static void lpyParameters(App& app) {
    auto plant = app.state.plant();
    int n = plant->iterations;
    if (ImGui::SliderInt("derivation length", &n, 0, std::max(12, plant->iterations + 2))) app.state.setIterations(n);
    const std::string& text = app.state.text();
    int id = 0;
    static std::uint64_t gesture = 0;  // a slider's drag: one undo step
    bool inCategory = false, shown = true;  // under a heading; whether it is open
    for (const LpyScalar& s : lpyScalars(text)) {
        ImGui::PushID(id++);
        if (s.kind == LpyScalar::Kind::Category) {  // Studio's heading: the scalars after it, folded
            if (inCategory && shown) ImGui::TreePop();
            inCategory = true;
            shown = ImGui::TreeNodeEx(s.name.c_str(), ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_SpanAvailWidth);
            scalarMenu(app, s);
            ImGui::PopID();
            continue;
        }
        if (!shown) {
            ImGui::PopID();
            continue;
        }
        bool changed = false;
        double value = 0;
        if (s.kind == LpyScalar::Kind::Bool) {
            bool on = s.value != 0;
            changed = ImGui::Checkbox(s.name.c_str(), &on);
            value = on ? 1 : 0;
        } else if (s.kind == LpyScalar::Kind::Integer) {
            int v = saturate<int>(s.value);
            changed = ImGui::SliderInt(s.name.c_str(), &v, saturate<int>(s.min), saturate<int>(s.max));
            value = v;
        } else {
            float v = toFloat(s.value);
            changed = ImGui::SliderFloat(s.name.c_str(), &v, toFloat(s.min), toFloat(s.max), "%.3g");
            value = v;
        }
        if (ImGui::IsItemActivated()) gesture = newGesture();
        if (changed) app.state.setText(setLpyScalar(text, s, value), gesture);
        scalarMenu(app, s);
        ImGui::PopID();
    }
    if (inCategory && shown) ImGui::TreePop();
    newScalar(app);
}

void parameterSection(App& app) {
    auto plant = app.state.plant();
    if (plant && plant->image) {
        ifsMaps(app);
        return;
    }
    if (!plant || !plant->grammar) return;
    if (app.state.kind() == FileKind::Lpy) {
        lpyParameters(app);
        return;
    }
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

void vlabSection(App& app, const VlabSummary& object) {
    ImGui::TextColored(kDim, "%s", object.folder.c_str());
    if (!object.description.empty()) ImGui::TextWrapped("%s", object.description.c_str());
    std::string files;
    for (const auto& f : object.files) files += (files.empty() ? "" : "  ") + f;
    ImGui::TextColored(kDim, "files:");
    ImGui::SameLine();
    ImGui::TextWrapped("%s", files.c_str());
    for (const auto& n : object.notes) ImGui::TextColored(kWarning, "%s", n.c_str());
    // Its control panels: each slider or button rewrites its #define, as VLab's panel does.
    auto plant = app.state.plant();
    if (!plant || !plant->grammar) return;
    for (const VlabPanel& panel : object.panels) {
        ImGui::Separator();
        ImGui::TextUnformatted(panel.name.empty() ? "panel" : panel.name.c_str());
        for (const VlabPanelItem& item : panel.items) {
            auto it = plant->grammar->defines.find(item.define);
            if (it == plant->grammar->defines.end()) continue;  // not a number the grammar defines
            const std::string id = item.label + "##" + item.define + (item.slider ? "" : std::to_string(item.value));
            if (item.slider) {
                float f = toFloat(it->second);
                const bool whole = item.divisor == 1 && item.min == std::floor(item.min) && item.max == std::floor(item.max) &&
                                   std::fabs(item.min) < 1e9 && std::fabs(item.max) < 1e9;
                if (whole) {
                    int v = int(std::lround(it->second));
                    if (ImGui::SliderInt(id.c_str(), &v, int(item.min), int(item.max))) app.state.setDefineValue(item.define, float(v));
                } else if (ImGui::SliderFloat(id.c_str(), &f, float(item.min), float(item.max), "%.3g")) {
                    app.state.setDefineValue(item.define, f);
                }
            } else if (ImGui::RadioButton(id.c_str(), it->second == item.value)) {
                app.state.setDefineValue(item.define, float(item.value));
            }
        }
    }
}

void growthSection(App& app) {
    auto plant = app.state.plant();
    if (!plant) return;
    int step = plant->displayStep;
    // A VLab object's animation file: the steps from its first frame to its last.
    int first = 0, last = plant->iterations;
    if (const auto& p = plant->grammar ? plant->grammar->settings.picture : std::nullopt; p && !p->frames.empty())
        first = std::min(p->frames.front(), last), last = std::max(first, std::min(p->frames.back(), last));
    if (ImGui::SliderInt("step", &step, first, last)) app.state.setDisplayStep(step);
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
    ImGui::SameLine();
    ImGui::Checkbox("full quality moving", &v.fullWhileMoving);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Draws the still picture in every frame while the view moves, however long it takes.\n"
                          "Off, a plant whose picture takes a few ms (a GPU, a small plant) moves at full\n"
                          "quality anyway, and others as a lighter picture, to keep sixty frames a second.");
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

}  // namespace sprout::viewer::detail
