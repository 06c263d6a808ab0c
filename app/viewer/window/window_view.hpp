#pragma once
// Private to app/viewer: the 3D view beside the panel, for the main loop (window.cpp): the
// plant taken from the worker to the GPU, its picture drawn when something changed (moving
// frames at a fitted resolution, the still picture refined a piece per frame), and what
// ImGui draws over the view.
#include <cstdint>

#include "app/viewer/window/app.hpp"

namespace sprout::viewer::detail {

// What a pass of the main loop did, for the rest of it: the plant's part (takePlant), the
// view's (drawView), then the frame's time and statistics (noteFrame).
struct Frame {
    bool uploadedNow = false;   // a new plant went to the GPU (or began to) in this frame
    bool refinedPiece = false;  // a piece of the still view drawn in this frame
    bool moved = false;         // the moving view drawn in this frame
    bool viewUpdated = false;   // the view's picture changed in this frame
    bool previewed = false;     // a new scene's moving-quality picture drawn in this frame
    std::uint64_t uiHash = 0;   // drawDataHash of this frame's panel, when made
    bool present = true;        // the frame is shown (see drawView)
    double measuringMs = 0;     // spent measuring for a script (not the frame's own time)
    bool mayKeepView = false;   // the back buffer's view may stay as it is (Presenter::mayKeepView)
    bool viewShown = false;     // the view's picture was put in the back buffer in this frame
};

// The plant the worker hands over, if any (App::state.update): a density image to its texture,
// a plant to the GPU, whole or a piece per frame (the plant on screen stays until the new one
// is whole), framed anew when it differs; then a pending pick, the highlight and environment.
void takePlant(App& app, Frame& frame);

// Storage for the view's picture, w x h: a texture, as a moving frame's smaller picture is
// drawn stretched over the view.
void makeViewPicture(unsigned texture, int w, int h);

// Labels (L-Py's @L) over the 3D view, where the camera shows their points, in the panel's font
// with a dark outline (as `paintLabels` paints them into pictures).
void drawLabels(App& app, int fw, int fh);

// An iterated function system's density image, fitted to the view (vw x vh) as an ImGui window.
void showDensityImage(App& app, int vw, int vh);

// The plant's view (vw x vh, right of the panel in the fw x fh window), redrawn only when
// something changed: moving frames while dragged or played, else the still picture a piece
// per frame; shown in the window's back buffer unless nothing on screen changes.
void drawView(App& app, Frame& frame, int vw, int vh, int fw, int fh);

// After a frame (app.frameMs set): the moving view's resolution fitted to its frames' time,
// and the moving frames' statistics.
void noteFrame(App& app, const Frame& frame);

}  // namespace sprout::viewer::detail
