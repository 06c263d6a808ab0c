// The panel's Materials section (issue 52): an L-Py model's colour map (app/plant/
// lpy_materials.hpp), each material's colours, diffuse factor, shininess and transparency set
// with Dear ImGui's colour editors and sliders. What they change is written in the model's
// text as L-Py Studio writes it, and the worker derives the model again; a whole drag of a
// slider is one undo step.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <filesystem>
#include <map>

#include "app/mesh/texture_images.hpp"
#include "app/plant/lpy_materials.hpp"
#include "app/render/gl.hpp"
#include "app/viewer/window/panel_sections.hpp"

namespace sprout::viewer::detail {
namespace {

const std::vector<LpyMaterial>& materialsOf(const std::string& text) {
    static std::string read;
    static std::vector<LpyMaterial> materials;
    if (text != read) read = text, materials = lpyMaterials(text);
    return materials;
}

// A texture's image as a GL texture for the panel (made again when the file changes); 0: none.
unsigned thumbnail(const std::string& path, const mesh::TextureImage** shown) {
    static std::map<std::string, std::pair<std::shared_ptr<const mesh::TextureImage>, unsigned>> made;
    const auto image = mesh::textureImage(path);
    *shown = image.get();
    auto& [kept, texture] = made[path];
    if (kept == image) return texture;
    kept = image;
    if (!image->error.empty()) return 0;
    if (!texture) glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image->width, image->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image->rgba.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

// A texture material: its image (found beside the model, as the drawing finds it) and its file,
// which the field changes (one undo step).
void textureEditor(App& app, const LpyMaterial& m) {
    std::filesystem::path file(m.texture);
    if (file.is_relative() && !app.state.path().empty()) file = app.state.path().parent_path() / file;
    const mesh::TextureImage* image = nullptr;
    if (const unsigned t = thumbnail(file.string(), &image); t && image) {
        const float w = std::min(160.0f, ImGui::GetContentRegionAvail().x), h = w * float(image->height) / float(std::max(1, image->width));
        ImGui::Image(reinterpret_cast<ImTextureID>(std::uintptr_t(t)), ImVec2(w, h));
        ImGui::TextColored(kDim, "%d x %d %s, times the texture's colour", image->width, image->height, image->format.c_str());
    } else if (image) {
        ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.4f, 1.0f), "%s: drawn in its colour", image->error.c_str());
    }
    static char name[512];
    static int editing = -1;
    static bool typing = false;  // the field was being typed in last frame: its text is the user's
    if (editing != m.index || !typing) std::snprintf(name, sizeof name, "%s", m.texture.c_str()), editing = m.index;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    const bool entered = ImGui::InputText("image file", name, sizeof name, ImGuiInputTextFlags_EnterReturnsTrue);
    typing = ImGui::IsItemActive();
    if (entered && m.texture != name) {
        std::string error;
        const std::string text = setLpyTextureFile(app.state.text(), m, name, error);
        if (text.empty()) app.say(error);
        else app.state.setText(text, newGesture());
    }
}

// The material the text has now with that index (the last, as L-Py's turtle keeps it).
const LpyMaterial* materialAt(const std::string& text, int index) {
    const LpyMaterial* found = nullptr;
    for (const LpyMaterial& m : materialsOf(text))
        if (m.index == index) found = &m;
    return found;
}

ImVec4 swatch(const LpyMaterial& m) {
    const auto c = lpyDiffuseColour(m);
    return ImVec4(float(c[0]) / 255, float(c[1]) / 255, float(c[2]) / 255, float(1 - m.transparency));
}

// One widget of the open material: its change written with the widget's gesture.
void write(App& app, const LpyMaterial& m, LpyMaterial::Field f, const LpyMaterial& v, bool changed, std::uint64_t& gesture) {
    if (ImGui::IsItemActivated()) gesture = newGesture();
    if (changed) app.state.setText(setLpyMaterial(app.state.text(), m, f, v), gesture);
}

bool colourEdit(const char* label, std::array<int, 3>& c) {
    float f[3] = {float(c[0]) / 255, float(c[1]) / 255, float(c[2]) / 255};
    if (!ImGui::ColorEdit3(label, f, ImGuiColorEditFlags_Uint8)) return false;
    for (size_t i = 0; i < 3; ++i) c[i] = int(std::lround(std::clamp(f[i], 0.0f, 1.0f) * 255));
    return true;
}

}  // namespace

bool hasLpyMaterials(App& app) { return !materialsOf(app.state.text()).empty(); }

void materialSection(App& app) {
    static int open = -1;
    static std::uint64_t gesture = 0;
    const std::vector<LpyMaterial> materials = materialsOf(app.state.text());  // a copy: a write reads them again
    if (std::none_of(materials.begin(), materials.end(), [](const LpyMaterial& m) { return m.index == open; })) open = materials.front().index;
    for (const LpyMaterial& m : materials) {
        ImGui::PushID(m.index);
        ImGui::ColorButton("##swatch", swatch(m), ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_AlphaPreview, ImVec2(28, 16));
        ImGui::SameLine();
        char label[160];
        std::snprintf(label, sizeof label, "%d  %s%s%s", m.index, m.name.c_str(), m.texture.empty() ? "" : "texture ", m.texture.c_str());
        if (ImGui::Selectable(label, open == m.index)) open = m.index;
        ImGui::PopID();
    }
    // A range of the colour map interpolated between its two ends, as L-Py's colour map does.
    static int from = 0, to = 0;
    if (to <= from) from = materials.front().index, to = materials.back().index;
    ImGui::SetNextItemWidth(160);
    ImGui::DragIntRange2("range", &from, &to, 0.2f, 0, 255);
    ImGui::SameLine();
    if (ImGui::SmallButton("interpolate")) {
        std::string error;
        const std::string text = interpolateLpyMaterials(app.state.text(), from, to, error);
        if (text.empty()) app.say(error);
        else app.state.setText(text, newGesture());
    }
    const LpyMaterial* shown = materialAt(app.state.text(), open);
    if (!shown) return;
    const LpyMaterial m = *shown;
    if (!m.texture.empty()) {
        textureEditor(app, m);
        return;
    }
    LpyMaterial v = m;
    ImGui::PushID("material");
    write(app, m, LpyMaterial::Ambient, v, colourEdit("ambient", v.ambient), gesture);
    float diffuse = float(v.diffuse), shininess = float(v.shininess), transparency = float(v.transparency);
    // PlantGL keeps ambient x diffuse within 255: the slider goes as far as that.
    const float most = float(std::min(lpyMostDiffuse(v.ambient), 100.0));
    bool changed = ImGui::SliderFloat("diffuse", &diffuse, 0.0f, most, "%.3g", ImGuiSliderFlags_AlwaysClamp);
    v.diffuse = double(diffuse);
    write(app, m, LpyMaterial::Diffuse, v, changed, gesture);
    write(app, m, LpyMaterial::Specular, v, colourEdit("specular", v.specular), gesture);
    write(app, m, LpyMaterial::Emission, v, colourEdit("emission", v.emission), gesture);
    changed = ImGui::SliderFloat("shininess", &shininess, 0.0f, 1.0f, "%.3g");
    v.shininess = double(shininess);
    write(app, m, LpyMaterial::Shininess, v, changed, gesture);
    changed = ImGui::SliderFloat("transparency", &transparency, 0.0f, 1.0f, "%.3g");
    v.transparency = double(transparency);
    write(app, m, LpyMaterial::Transparency, v, changed, gesture);
    ImGui::PopID();
    ImGui::TextColored(kDim, "drawn in its diffuse colour (ambient x diffuse)");
}

std::vector<std::string> materialLines(App& app) {
    std::vector<std::string> out;
    for (const LpyMaterial& m : materialsOf(app.state.text())) {
        char buf[400];
        std::snprintf(buf, sizeof buf, "material=%d name=%s ambient=%d,%d,%d diffuse=%g specular=%d,%d,%d emission=%d,%d,%d shininess=%g transparency=%g%s%s",
                      m.index, m.name.c_str(), m.ambient[0], m.ambient[1], m.ambient[2], m.diffuse, m.specular[0], m.specular[1], m.specular[2],
                      m.emission[0], m.emission[1], m.emission[2], m.shininess, m.transparency, m.texture.empty() ? "" : " texture=",
                      m.texture.c_str());
        out.push_back(buf);
    }
    return out;
}

std::string setMaterialField(App& app, int index, const std::string& field, const std::vector<double>& values, std::uint64_t gesture) {
    const LpyMaterial* m = materialAt(app.state.text(), index);
    if (m && !m->texture.empty() && field.rfind("image ", 0) == 0) {  // a texture's file: "image NAME"
        std::string error;
        const std::string text = setLpyTextureFile(app.state.text(), *m, field.substr(6), error);
        if (text.empty()) return error;
        app.state.setText(text, gesture ? gesture : newGesture());
        return "";
    }
    if (!m || !m->texture.empty()) return "no material " + std::to_string(index);
    const auto f = lpyMaterialFieldNamed(field);
    if (!f) return "no field " + field + " (ambient, diffuse, specular, emission, shininess, transparency)";
    const bool colour = *f == LpyMaterial::Ambient || *f == LpyMaterial::Specular || *f == LpyMaterial::Emission;
    if (values.size() != (colour ? 3u : 1u)) return field + " takes " + (colour ? "three numbers (0 to 255)" : "one number");
    LpyMaterial v = *m;
    std::array<int, 3> c{};
    for (size_t i = 0; colour && i < 3; ++i) c[i] = int(std::lround(std::clamp(values[i], 0.0, 255.0)));
    switch (*f) {
        case LpyMaterial::Ambient: v.ambient = c; break;
        case LpyMaterial::Specular: v.specular = c; break;
        case LpyMaterial::Emission: v.emission = c; break;
        case LpyMaterial::Diffuse: v.diffuse = std::clamp(values[0], 0.0, lpyMostDiffuse(v.ambient)); break;
        case LpyMaterial::Shininess: v.shininess = std::clamp(values[0], 0.0, 1.0); break;
        case LpyMaterial::Transparency: v.transparency = std::clamp(values[0], 0.0, 1.0); break;
    }
    const LpyMaterial was = *m;  // the cache's: read before the text changes
    app.state.setText(setLpyMaterial(app.state.text(), was, *f, v), gesture ? gesture : newGesture());
    return "";
}

}  // namespace sprout::viewer::detail
