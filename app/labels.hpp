#pragma once
// Labels (Geometry::labels, L-Py's @L) painted into a picture: each text where the camera sees
// its point, in ImGui's built-in font (13 pixels, scaled by whole pixels for larger sizes),
// with a dark outline so it reads on sky and plant alike. On the CPU, so that headless
// pictures carry them as the window shows them.
#include "app/image.hpp"
#include "app/render/camera.hpp"
#include "core/turtle/geometry.hpp"

namespace sprout {

// Where the camera shows `p` in a picture of w x h (x right, y down, from the top-left
// corner); false behind the camera.
bool labelPosition(const render::Camera& camera, int w, int h, const glm::vec3& p, float& x, float& y);

void paintLabels(Image& image, const Geometry& g, const render::Camera& camera);

}  // namespace sprout
