#pragma once
// A VLab object's picture (issue 50): its view file, animation file, material sets and colour
// maps (core/language/vlab/) read from its folder, and applied as cpfg applies them: the
// turtle's angle, colour index, widths and tropism reach the grammar's Settings; the camera,
// light, background, window size and animated steps its Settings::picture, which the
// renderer's callers frame the picture with (app/snapshot, the viewer).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/base/shine.hpp"

#include "app/plant/vlab_object.hpp"
#include "app/plant/vlab_panel.hpp"
#include "core/language/grammar.hpp"
#include "core/language/vlab/animation_file.hpp"
#include "core/language/vlab/background_scene.hpp"
#include "core/language/vlab/view_file.hpp"

namespace sprout {

struct VlabPicture {
    std::optional<vlab::ViewFile> view;
    std::optional<vlab::AnimationFile> animation;
    // cpfg's colour indices from the reference set on (index k is cpfg's 256 c + k), 0xRRGGBBAA;
    // empty when the object names no material set or colour map.
    std::vector<std::uint32_t> palette;
    // The palette entries whose material has a specular colour (medit's specular and
    // shininess, the exponent cpfg gives OpenGL), by index.
    std::vector<std::pair<int, Shine>> shines;
    std::optional<std::uint32_t> background;  // 0xRRGGBB: colour 0 of the map, or material 0's emission
    int width = 0, height = 0;
    // The view file's `background scene:`, read (vlab_background.hpp); null when none is drawn.
    std::shared_ptr<const vlab::BackgroundScene> backgroundScene;
    // What is wrong in these files, each a whole line with its file (FILE:line:col: or
    // FILE: byte N:); cpfg goes on with its defaults, and so does Sprout.
    std::vector<std::string> notes;
};

// The object's files read (missing ones are notes).
VlabPicture readVlabPicture(const VlabObject& object);

// The VLab object `path` opens: the folder itself, or the folder of a file in it, when that
// folder has a `specifications` (File > Open and `sprout FOLDER` in the viewer).
std::optional<VlabObject> vlabObjectAt(const std::string& path);

// What the viewer's panel shows of an object: its folder, its description.txt, its files, and
// what is wrong in them.
struct VlabSummary {
    std::string folder, description;
    std::vector<std::string> files;
    std::vector<std::string> notes;
    std::vector<VlabPanel> panels;  // its L-system's control panels (vlab_panel.hpp)
    bool animate = false;           // cpfg's -a: the viewer opens playing
};
VlabSummary summarizeVlabObject(const VlabObject& object);

// `picture` applied to a grammar's settings (its derivation length already read).
void applyVlabPicture(const VlabPicture& picture, Settings& settings);

// When `lsystemPath` is the L-system of the VLab object in its folder (its cpfg line runs it),
// that object's picture applied to `settings`; false, nothing changed, otherwise.
bool applyVlabObjectOf(const std::string& lsystemPath, Settings& settings);

}  // namespace sprout
