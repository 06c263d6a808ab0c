#pragma once
// A VLab object's background scene (issue 50): the files its view file's `background scene:`
// names, read as cpfg reads them (core/language/vlab/background_scene.hpp), with what cpfg
// draws them in: colour index 0 of the reference set (its material, or its colour map's
// entry), `contour sides:` and `tapered lines:`. vlab_view.cpp puts the scene in the picture
// (PictureView::backgroundScene); growth.cpp draws it after the plant (core/turtle/
// background_scene.hpp), so the picture, the viewer and the exports show it.
#include <memory>
#include <string>
#include <vector>

#include "app/plant/vlab_object.hpp"
#include "core/language/grammar.hpp"
#include "core/language/vlab/background_scene.hpp"
#include "core/language/vlab/view_file.hpp"
#include "core/turtle/geometry.hpp"

namespace sprout {

// The scene `view` (the object's view file) names; null when it names none, or when the object
// has no material set or colour map (cpfg then draws none: "cannot be drawn in index mode").
// The files' problems are appended to `notes`, each a whole line naming its file and line.
std::shared_ptr<const vlab::BackgroundScene> readVlabBackground(const VlabObject& object, const vlab::ViewFile& view,
                                                                std::vector<std::string>& notes);

// The background scene of `settings`' picture drawn into `out` after the plant (nothing when
// it has none).
void drawPictureBackground(const Settings& settings, Geometry& out);

}  // namespace sprout
