#include "app/plant/vlab_background.hpp"

#include <filesystem>

#include "core/base/read_file.hpp"
#include "core/language/vlab/colours.hpp"
#include "core/turtle/background_scene.hpp"

namespace sprout {
namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxFiles = 64;  // on one `background scene:` line

// cpfg's colour for the scene: index 0 of the reference set (clp.colormap), of the kind of
// colour file cpfg reads (the later option's).
void startColour(const VlabObject& object, vlab::BackgroundScene& scene) {
    scene.materials = object.colourFiles.back().material;
    for (const auto& f : object.colourFiles) {
        if (f.material != scene.materials || f.set != object.referenceSet) continue;
        const std::optional<std::string> bytes = readFile(f.path);
        std::string error;
        if (!bytes) continue;  // vlab_view.cpp notes it
        if (scene.materials) {
            if (auto set = vlab::readMaterials(*bytes, error)) scene.start = set->materials[0].value_or(vlab::Material{});
        } else if (auto map = vlab::readColourMap(*bytes, error)) {
            scene.startColour = map->colours[0];
        }
    }
}

}  // namespace

std::shared_ptr<const vlab::BackgroundScene> readVlabBackground(const VlabObject& object, const vlab::ViewFile& view,
                                                                std::vector<std::string>& notes) {
    auto scene = std::make_shared<vlab::BackgroundScene>();
    const fs::path folder = fs::path(object.view).parent_path();
    const vlab::FileReference* first = nullptr;
    size_t files = 0;
    for (const vlab::FileReference& f : view.files) {
        if (f.command != "background scene") continue;
        if (!first) first = &f;
        if (++files > kMaxFiles) {
            notes.push_back(formatDiagnostic({f.line, 1, "more than 64 background-scene files: the rest are not read", Severity::Warning}, object.view));
            break;
        }
        vlab::loadBackgroundScene(folder / f.file, *scene);
    }
    if (!first) return nullptr;
    if (object.colourFiles.empty()) {
        notes.push_back(formatDiagnostic({first->line, 1,
                                          "cpfg draws a background scene only with a material set or a colour map (-M or -m on "
                                          "its cpfg line): '" + first->file + "' is not drawn",
                                          Severity::Warning},
                                         object.view));
        return nullptr;
    }
    for (const auto& p : scene->problems) notes.push_back(p.text());
    startColour(object, *scene);
    scene->sides = view.contourSides;
    scene->tapered = view.taperedLines;
    return scene;
}

void drawPictureBackground(const Settings& settings, Geometry& out) {
    if (settings.picture && settings.picture->backgroundScene) drawBackgroundScene(*settings.picture->backgroundScene, out);
}

}  // namespace sprout
