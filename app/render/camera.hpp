#pragma once
// An orbit camera around a target: yaw and pitch in degrees, distance, perspective or
// orthographic. Frames a plant's bounds on load.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/turtle/geometry.hpp"

namespace sprout::render {

struct Camera {
    glm::vec3 target{0, 0, 0};
    float yaw = 0;     // degrees about +Y; 0 looks at the front (from +Z)
    float pitch = 0;   // degrees; positive looks down on the plant
    float distance = 10;
    float fovY = 35;   // degrees (perspective)
    bool orthographic = false;
    float orthoHeight = 10;  // visible height (orthographic)
    float roll = 0;    // degrees the picture turns about the viewing direction (cpfg's twist)

    // Closer (k < 1) or farther (k > 1), distance and orthographic height together, kept
    // between 1e-6 and 1e12 whatever the wheel, the keys or a script ask: a zoom to 0 or to
    // infinity would make the projection NaN.
    void zoom(float k);
    glm::vec3 eye() const;
    glm::mat4 view() const;
    glm::mat4 projection(float aspect, float near, float far) const;
};

enum class ViewPreset { Auto, Front, Side, Top, Iso };

// A camera that shows the whole of `bounds` with a margin, from the given direction.
// Planar curves get an orthographic front view; flat plants (z = 0) a front view.
Camera frameBounds(const Bounds& bounds, float aspect, ViewPreset view, bool planarCurve);

// A view given as cpfg's view file gives it: from `eye` towards `target`, turned by `roll`
// degrees, parallel or perspective (`fovY`), closer by `scale`.
struct ViewDirection {
    glm::vec3 eye{0, 0, 1}, target{0, 0, 0};
    float roll = 0;
    bool perspective = false;
    float fovY = 45;
    float scale = 1;
};

// A camera that looks along `view`'s direction at the centre of `bounds`, which fill the frame
// (cpfg's automatic window), then zoomed by its scale.
Camera frameView(const Bounds& bounds, float aspect, const ViewDirection& view);

// The same direction, fitted to the plant's own points rather than its bounding box: a
// round crown fills the frame instead of its box's projection.
Camera frameGeometry(const Geometry& geometry, float aspect, ViewPreset view);

}  // namespace sprout::render
