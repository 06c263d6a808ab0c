#include "app/plant/vlab_view.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "app/plant/vlab_background.hpp"
#include "core/base/read_file.hpp"
#include "core/language/vlab/colours.hpp"

namespace sprout {
namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t kNoColour = 0xC8C8C8FF;  // cpfg's default colour map item (200, 200, 200)

void noteAll(const std::vector<Diagnostic>& ds, const std::string& file, std::vector<std::string>& notes) {
    for (const Diagnostic& d : ds) notes.push_back(formatDiagnostic(d, file));
}

// The object's material sets and colour maps as one table from the reference set on. cpfg
// reads one kind: the later option's (control.c: "later wins").
void readColours(const VlabObject& object, VlabPicture& out) {
    if (object.colourFiles.empty()) return;
    const bool materials = object.colourFiles.back().material;
    std::vector<std::optional<std::vector<std::uint32_t>>> sets(12);
    std::vector<std::vector<std::pair<int, Shine>>> setShines(12);  // by index within each set
    for (const auto& f : object.colourFiles) {
        if (f.material != materials) continue;  // the other kind: cpfg does not read it
        std::optional<std::string> bytes = readFile(f.path);
        std::string error;
        if (!bytes) {
            out.notes.push_back(formatDiagnostic({f.line, f.col, f.path + " cannot be opened; cpfg's default colours used", Severity::Warning},
                                                 object.specifications));
            continue;
        }
        std::vector<std::uint32_t> colours(256, kNoColour);
        if (materials) {
            auto set = vlab::readMaterials(*bytes, error);
            if (!set) {
                out.notes.push_back(f.path + ": " + error);
                continue;
            }
            const vlab::Material white;  // cpfg's default material: diffuse white
            for (size_t k = 0; k < 256; ++k) {
                const vlab::Material& m = set->materials[k].value_or(white);
                // The colour is the diffuse one; the emission is light of its own, added after
                // the lighting as OpenGL adds it (a shine's), not a brighter colour shaded.
                vlab::Material diffuse = m;
                diffuse.emission = {0, 0, 0};
                colours[k] = vlab::materialColour(diffuse);
                auto c = [&](const std::array<float, 3>& rgb, size_t i) {
                    return std::uint32_t(std::lround(std::clamp(rgb[i], 0.0f, 1.0f) * 255.0f));
                };
                auto rgb = [&](const std::array<float, 3>& v) { return c(v, 0) << 24 | c(v, 1) << 16 | c(v, 2) << 8; };
                const Shine shine{rgb(m.specular), std::clamp(m.shininess / 128.0f, 0.0f, 1.0f), rgb(m.emission)};
                if (!shine.plain()) setShines[size_t(f.set)].push_back({int(k), shine});
            }
            if (size_t(f.set) == size_t(object.referenceSet) && set->materials[0]) {
                const auto& e = set->materials[0]->emission;
                auto c = [](float v) { return std::uint32_t(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); };
                out.background = c(e[0]) << 16 | c(e[1]) << 8 | c(e[2]);
            }
        } else {
            auto map = vlab::readColourMap(*bytes, error);
            if (!map) {
                out.notes.push_back(f.path + ": " + error);
                continue;
            }
            for (size_t k = 0; k < 256; ++k) colours[k] = map->colours[k] << 8 | 0xFF;
            if (f.set == object.referenceSet) out.background = map->colours[0];
        }
        sets[size_t(f.set)] = std::move(colours);
    }
    int last = -1;
    for (int k = 0; k < 12; ++k)
        if (sets[size_t(k)]) last = k;
    for (int k = object.referenceSet; k <= last; ++k) {
        const auto& s = sets[size_t(k)];
        const int first = int(out.palette.size());
        for (size_t i = 0; i < 256; ++i) out.palette.push_back(s ? (*s)[i] : kNoColour);
        if (s)
            for (const auto& [i, shine] : setShines[size_t(k)]) out.shines.push_back({first + i, shine});
    }
}

}  // namespace

VlabPicture readVlabPicture(const VlabObject& object) {
    VlabPicture out;
    if (!object.view.empty()) {
        if (std::optional<std::string> text = readFile(object.view)) {
            out.view = vlab::readViewFile(*text);
            noteAll(out.view->diagnostics, object.view, out.notes);
        } else {
            out.notes.push_back(object.view + ": cannot be opened; cpfg's default view used");
        }
    }
    if (!object.animation.empty()) {
        if (std::optional<std::string> text = readFile(object.animation)) {
            out.animation = vlab::readAnimationFile(*text);
            noteAll(out.animation->diagnostics, object.animation, out.notes);
        } else {
            out.notes.push_back(object.animation + ": cannot be opened; cpfg's default animation used");
        }
    }
    readColours(object, out);
    if (out.view) out.backgroundScene = readVlabBackground(object, *out.view, out.notes);
    out.width = object.width;
    out.height = object.height;
    return out;
}

void applyVlabPicture(const VlabPicture& p, Settings& st) {
    PictureView picture;
    if (const auto& v = p.view) {
        st.angle = {v->angleIncrement.value_or(45.0), 0};  // cpfg's angle comes from its view file only
        if (v->lineWidth && v->lineStyle != vlab::LineStyle::Pixel) {
            st.width = *v->lineWidth;  // in the turtle's units, as F's step
            st.widthIncrement = v->widthIncrement;
        }
        // Lines with a width in the turtle's units are solids, never a flat curve's ink.
        if (v->lineStyleSet && v->lineStyle != vlab::LineStyle::Pixel) st.view = ViewHint::Solid;
        for (const vlab::Movement& m : v->movements) st.movements.push_back({m.torque, m.direction, m.angle, m.elasticity, m.step});
        st.initialScale = v->initialScale;  // cpfg's turtle scale, which @D, @Di, @Dd change
        st.scaleMultiplier = v->scaleMultiplier;
        if (v->tropismDirection) {
            st.tropism = *v->tropismDirection;
            st.tropismStrength = v->elasticity;
        }
        picture.eye = v->viewpoint;
        picture.target = v->reference;
        picture.twist = v->twist / 10.0;
        picture.perspective = v->perspective;
        picture.viewingAngle = v->viewingAngle;
        picture.scale = v->scale;
        picture.light = v->lights.empty() || !v->lights.front().directional || v->lightDirectionSet ? v->lightDirection : v->lights.front().vector;
    }
    if (!p.palette.empty()) {
        st.palette = p.palette;
        st.shines = p.shines;
        st.initialColour = p.view ? p.view->initialColour.value_or(128) : 128;
        st.colourIncrement = p.view ? p.view->colourIncrement : 1;
        st.gradient = Toggle::Off;
        picture.ink = st.palette[size_t(st.initialColour) % st.palette.size()] >> 8;
    }
    picture.background = p.background;
    picture.backgroundScene = p.backgroundScene;
    picture.width = p.width;
    picture.height = p.height;
    if (p.animation) picture.frames = p.animation->frames(st.iterations);
    st.picture = picture;
}

std::optional<VlabObject> vlabObjectAt(const std::string& path) {
    std::error_code ec;
    const fs::path p(path);
    const fs::path folder = fs::is_directory(p, ec) ? p : p.parent_path();
    if (!fs::is_regular_file(folder / "specifications", ec)) return std::nullopt;
    return readVlabObject(folder.empty() ? "." : folder.string());
}

VlabSummary summarizeVlabObject(const VlabObject& object) {
    VlabSummary out;
    const fs::path folder = fs::path(object.specifications).parent_path();
    out.folder = folder.string();
    out.description = readFile(folder / "description.txt").value_or("");
    out.animate = object.animate;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(folder, ec))
        if (e.is_regular_file(ec)) out.files.push_back(e.path().filename().string());
    std::sort(out.files.begin(), out.files.end());
    for (const Diagnostic& d : object.diagnostics) out.notes.push_back(formatDiagnostic(d, object.specifications));
    for (std::string& n : readVlabPicture(object).notes) out.notes.push_back(std::move(n));
    out.panels = vlabPanelsOf(folder.string(), fs::path(object.lsystem).filename().string());
    for (const VlabPanel& p : out.panels)
        for (const std::string& n : p.problems) out.notes.push_back(n);
    return out;
}

bool applyVlabObjectOf(const std::string& lsystemPath, Settings& settings) {
    if (lsystemPath.empty()) return false;
    std::error_code ec;
    const fs::path folder = fs::path(lsystemPath).parent_path();
    if (!fs::is_regular_file(folder / "specifications", ec)) return false;
    std::optional<VlabObject> object = readVlabObject(folder.empty() ? "." : folder.string());
    if (!object || hasErrors(object->diagnostics) || !fs::equivalent(object->lsystem, lsystemPath, ec)) return false;
    applyVlabPicture(readVlabPicture(*object), settings);
    return true;
}

}  // namespace sprout
