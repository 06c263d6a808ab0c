// The panel's Colours section (issue 52): a VLab object's material sets (medit's `.mat`) and
// colour maps (palette's `.map`), the files its cpfg line names with -M and -m. The 256
// entries show as a grid; the one clicked is edited as medit edits a material (ambient,
// diffuse, specular, emission, shininess, transparency) or palette a colour, and a range of
// a map is interpolated between its ends. Every change is written to the file at once, in its
// editor's bytes, and the object is derived again; the section's undo takes it back.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/plant/vlab_edit.hpp"
#include "app/viewer/window/panel_sections.hpp"
#include "core/base/read_file.hpp"

namespace sprout::viewer::detail {
namespace {

struct ColourView {
    std::string path;
    size_t file = 0;
    int entry = 1, rangeFrom = 0, rangeTo = 15;
    std::uint64_t gesture = 0;
};

ColourView& view() {
    static ColourView v;
    return v;
}

const std::vector<VlabColourFile>& filesOf(App& app) {
    static std::string path;
    static std::vector<VlabColourFile> files;
    if (app.state.path().string() != path) path = app.state.path().string(), files = vlabColourFiles(path);
    return files;
}

ImVec4 toImGui(std::uint32_t rgb) { return ImVec4(float(rgb >> 16 & 0xFF) / 255, float(rgb >> 8 & 0xFF) / 255, float(rgb & 0xFF) / 255, 1); }

// One entry as the grid shows it: a map's colour, a material's diffuse plus emission.
std::uint32_t shown(const VlabColourFile& f, const std::string& bytes, int k, bool& present) {
    std::string error;
    present = true;
    if (!f.material) {
        const auto map = vlab::readColourMap(bytes, error);
        return map ? map->colours[size_t(k)] : 0;
    }
    const auto set = vlab::readMaterials(bytes, error);
    present = set && set->materials[size_t(k)];
    return present ? vlab::materialColour(*set->materials[size_t(k)]) >> 8 : 0x303030;
}

bool colour3(const char* label, std::array<float, 3>& c) {
    return ImGui::ColorEdit3(label, c.data(), ImGuiColorEditFlags_Uint8 | ImGuiColorEditFlags_NoOptions);
}

void materialEditor(App& app, ColourView& v, const VlabColourFile& f, const std::string& bytes) {
    std::string error;
    const auto set = vlab::readMaterials(bytes, error);
    if (!set) return (void)ImGui::TextColored(kError, "%s", error.c_str());
    vlab::Material m = set->materials[size_t(v.entry)].value_or(vlab::Material{{0.2f, 0.2f, 0.2f}, {0.8f, 0.8f, 0.8f}});  // medit's default
    bool changed = colour3("ambient", m.ambient);
    if (ImGui::IsItemActivated()) v.gesture = newGesture();
    changed |= colour3("diffuse", m.diffuse);
    if (ImGui::IsItemActivated()) v.gesture = newGesture();
    changed |= colour3("specular", m.specular);
    if (ImGui::IsItemActivated()) v.gesture = newGesture();
    changed |= colour3("emission", m.emission);
    if (ImGui::IsItemActivated()) v.gesture = newGesture();
    changed |= ImGui::SliderFloat("shininess", &m.shininess, 0, 128, "%.0f");
    if (ImGui::IsItemActivated()) v.gesture = newGesture();
    changed |= ImGui::SliderFloat("transparency", &m.transparency, 0, 1, "%.3f");
    if (ImGui::IsItemActivated()) v.gesture = newGesture();
    if (changed)
        if (auto out = materialsWith(bytes, v.entry, m, error)) writeObjectFile(app, f.path, *out, v.gesture);
}

void mapEditor(App& app, ColourView& v, const VlabColourFile& f, const std::string& bytes) {
    std::string error;
    const auto map = vlab::readColourMap(bytes, error);
    if (!map) return (void)ImGui::TextColored(kError, "%s", error.c_str());
    const std::uint32_t c = map->colours[size_t(v.entry)];
    std::array<float, 3> rgb{float(c >> 16 & 0xFF) / 255, float(c >> 8 & 0xFF) / 255, float(c & 0xFF) / 255};
    const bool changed = colour3("colour", rgb);
    if (ImGui::IsItemActivated()) v.gesture = newGesture();
    if (changed) {
        std::uint32_t out = 0;
        for (int i = 0; i < 3; ++i) out |= std::uint32_t(std::lround(std::clamp(rgb[size_t(i)], 0.0f, 1.0f) * 255)) << (16 - 8 * i);
        if (auto bytesOut = colourMapWith(bytes, v.entry, out, error)) writeObjectFile(app, f.path, *bytesOut, v.gesture);
    }
    ImGui::SetNextItemWidth(160);
    ImGui::DragIntRange2("range", &v.rangeFrom, &v.rangeTo, 0.2f, 0, 255);
    ImGui::SameLine();
    if (ImGui::SmallButton("interpolate"))
        if (auto out = colourMapInterpolated(bytes, v.rangeFrom, v.rangeTo, error)) writeObjectFile(app, f.path, *out, newGesture());
}

}  // namespace

bool hasVlabColours(App& app) { return !filesOf(app).empty(); }

void vlabColourSection(App& app) {
    ColourView& v = view();
    const auto& files = filesOf(app);
    if (v.path != app.state.path().string()) v = ColourView{app.state.path().string()};
    v.file = std::min(v.file, files.size() - 1);
    for (size_t i = 0; i < files.size(); ++i)
        if (ImGui::Selectable(files[i].label.c_str(), v.file == i)) v.file = i;
    const VlabColourFile& f = files[v.file];
    const std::string bytes = readFile(f.path).value_or("");
    // The 256 entries, 16 a row; the one open outlined.
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(1, 1));
    const float side = std::max(8.0f, std::floor((ImGui::GetContentRegionAvail().x - 16) / 16));
    for (int k = 0; k < 256; ++k) {
        bool present = true;
        const std::uint32_t c = shown(f, bytes, k, present);
        ImGui::PushID(k);
        if (k % 16) ImGui::SameLine();
        if (ImGui::ColorButton("##e", toImGui(c), ImGuiColorEditFlags_NoTooltip, ImVec2(side, side * 0.6f))) v.entry = k;
        if (k == v.entry)
            ImGui::GetWindowDrawList()->AddRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax(), IM_COL32(255, 200, 80, 255), 0, 0, 2);
        ImGui::PopID();
    }
    ImGui::PopStyleVar();
    ImGui::Text("entry %d", v.entry);
    if (f.material) materialEditor(app, v, f, bytes);
    else mapEditor(app, v, f, bytes);
    if (ImGui::SmallButton("undo##colours")) objectUndo(app, false);
    ImGui::SameLine();
    if (ImGui::SmallButton("redo##colours")) objectUndo(app, true);
}

std::vector<std::string> colourLines(App& app) {
    std::vector<std::string> out;
    for (const VlabColourFile& f : filesOf(app)) {
        const std::string bytes = readFile(f.path).value_or("");
        std::string line = "colour-file=" + f.label + " entries=";
        for (int k : {0, 1, 2, 3}) {
            bool present = true;
            char buf[32];
            std::snprintf(buf, sizeof buf, "%s%06X", k ? "," : "", shown(f, bytes, k, present));
            line += buf;
        }
        out.push_back(line + "...");
    }
    return out;
}

std::string setColourEntry(App& app, size_t file, int entry, const std::string& field, const std::vector<double>& values) {
    const auto& files = filesOf(app);
    if (file >= files.size()) return "no colour file " + std::to_string(file);
    const VlabColourFile& f = files[file];
    const std::string bytes = readFile(f.path).value_or("");
    std::string error;
    std::optional<std::string> out;
    auto rgb = [&](std::array<float, 3>& c) {
        for (size_t i = 0; i < 3 && i < values.size(); ++i) c[i] = float(std::clamp(values[i], 0.0, 255.0) / 255.0);
    };
    if (!f.material) {
        if (field == "interpolate") {
            out = colourMapInterpolated(bytes, entry, values.empty() ? entry : int(values[0]), error);
        } else {
            std::array<float, 3> c{};
            rgb(c);
            out = colourMapWith(bytes, entry, std::uint32_t(c[0] * 255) << 16 | std::uint32_t(c[1] * 255) << 8 | std::uint32_t(c[2] * 255), error);
        }
    } else {
        auto set = vlab::readMaterials(bytes, error);
        if (!set || entry < 0 || entry > 255) return error.empty() ? "no material " + std::to_string(entry) : error;
        vlab::Material m = set->materials[size_t(entry)].value_or(vlab::Material{{0.2f, 0.2f, 0.2f}, {0.8f, 0.8f, 0.8f}});
        if (field == "ambient") rgb(m.ambient);
        else if (field == "diffuse") rgb(m.diffuse);
        else if (field == "specular") rgb(m.specular);
        else if (field == "emission") rgb(m.emission);
        else if (field == "shininess" && !values.empty()) m.shininess = float(std::clamp(values[0], 0.0, 128.0));
        else if (field == "transparency" && !values.empty()) m.transparency = float(std::clamp(values[0], 0.0, 1.0));
        else return "no material field " + field;
        out = materialsWith(bytes, entry, m, error);
    }
    if (!out) return error;
    writeObjectFile(app, f.path, *out, newGesture());
    return "";
}

}  // namespace sprout::viewer::detail
