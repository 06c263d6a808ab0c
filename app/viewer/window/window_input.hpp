#pragma once
// Private to app/viewer: the window's mouse and keyboard, read once a frame by the main
// loop (window.cpp) after the panel: camera drags, the wheel, clicks that pick, shortcuts.
#include "app/viewer/window/app.hpp"

struct GLFWwindow;

namespace sprout::viewer::detail {

struct Mouse {
    bool rotating = false, panning = false;
    double x = 0, y = 0;
    double clickX = 0, clickY = 0;  // where the left button went down
    bool clickArmed = false;         // released there: a pick, not a drag
};

// Moves the camera, picks, and runs the keyboard shortcuts (listed in the help window, F1);
// `dt` is the frame's time in seconds.
void handleInput(App& app, GLFWwindow* window, Mouse& mouse, double dt);

}  // namespace sprout::viewer::detail
