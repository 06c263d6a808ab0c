// The window's input, once a frame: drags orbit or pan the camera, the wheel zooms, a click
// picks, and the keyboard shortcuts (handleInput, called by the main loop in window.cpp).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "app/viewer/window/app.hpp"
#include "app/viewer/window/window_input.hpp"

namespace sprout::viewer::detail {

void handleInput(App& app, GLFWwindow* window, Mouse& mouse, double dt) {
    // Camera: drag to orbit (left) or pan (right / middle), wheel to zoom.
    ImGuiIO& io = ImGui::GetIO();
    double mx = 0, my = 0;
    glfwGetCursorPos(window, &mx, &my);
    const bool overView = !io.WantCaptureMouse;
    if (overView && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        mouse.rotating = true;
        mouse.clickX = mx, mouse.clickY = my, mouse.clickArmed = true;  // a click, unless it drags
    }
    if (mouse.clickArmed && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
        mouse.clickArmed = false;
        if (std::abs(mx - mouse.clickX) + std::abs(my - mouse.clickY) < 4) app.pickAt(mx, my);
    }
    if (overView && (ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsMouseClicked(ImGuiMouseButton_Middle)))
        mouse.panning = true;
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) mouse.rotating = false;
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Right) && !ImGui::IsMouseDown(ImGuiMouseButton_Middle)) mouse.panning = false;
    const float ddx = float(mx - mouse.x), ddy = float(my - mouse.y);
    mouse.x = mx;
    mouse.y = my;
    app.interacting = mouse.rotating || mouse.panning || app.scriptDragging;
    const bool held = (ImGui::IsAnyItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left)) || app.scriptShaping;
    if (app.shapingHeld && !held) app.state.worker().settle();  // let go: only the last step's plant is of use now
    // Taking hold: the plants to come are drawn at the moving view's smallest size first (a
    // drag's first frames drew them at what the last camera drag had left, up to half the
    // window each way: 8-10 ms a frame on llvmpipe, 3-5 at a quarter); it grows as frames allow.
    if (!app.shapingHeld && held) app.movingScale = kSmallestMovingScale;
    app.shapingHeld = held;
    app.shaping = held || (app.shaping && app.state.worker().working());
    if (mouse.rotating && (ddx || ddy)) {
        app.camera.yaw -= ddx * 0.4f;
        app.camera.pitch = std::clamp(app.camera.pitch + ddy * 0.4f, -89.0f, 89.0f);
        app.needsRedraw = true;
    }
    if (mouse.panning && (ddx || ddy)) {
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(window, &fw, &fh);
        float scale = (app.camera.orthographic ? app.camera.orthoHeight
                                               : 2 * app.camera.distance * std::tan(glm::radians(app.camera.fovY) / 2)) /
                      float(std::max(fh, 1));
        glm::vec3 dir = glm::normalize(app.camera.eye() - app.camera.target);
        glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0, 1, 0), dir));
        glm::vec3 up = glm::cross(dir, right);
        app.camera.target += (-right * ddx + up * ddy) * scale;
        app.needsRedraw = true;
    }
    if (overView && io.MouseWheel != 0) {
        app.camera.zoom(std::pow(0.9f, io.MouseWheel));
        app.needsRedraw = true;
    }
    // Keyboard shortcuts (listed in the help window, F1).
    if (!io.WantTextInput) {
        if (ImGui::IsKeyPressed(GLFW_KEY_F)) app.frame();
        if (ImGui::IsKeyPressed(GLFW_KEY_R)) app.resetView();
        if (ImGui::IsKeyPressed(GLFW_KEY_T)) app.view.turntable = !app.view.turntable;
        if (ImGui::IsKeyPressed(GLFW_KEY_SPACE)) app.state.setPlaying(!app.state.playing());
        if (ImGui::IsKeyPressed(GLFW_KEY_LEFT)) app.state.stepBy(-1);
        if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT)) app.state.stepBy(1);
        if (ImGui::IsKeyPressed(GLFW_KEY_UP)) app.state.setIterations((app.state.plant() ? app.state.plant()->iterations : 0) + 1);
        if (ImGui::IsKeyPressed(GLFW_KEY_DOWN)) app.state.setIterations((app.state.plant() ? app.state.plant()->iterations : 1) - 1);
        if (ImGui::IsKeyPressed(GLFW_KEY_N)) app.state.newSpecimen();
        // Keyboard orbit and zoom: A / D turn around the plant, W / S tilt, Q / E zoom.
        const float orbit = 60.0f * float(dt), zoom = std::pow(0.4f, float(dt));
        if (ImGui::IsKeyDown(GLFW_KEY_A)) app.camera.yaw += orbit, app.needsRedraw = true;
        if (ImGui::IsKeyDown(GLFW_KEY_D)) app.camera.yaw -= orbit, app.needsRedraw = true;
        if (ImGui::IsKeyDown(GLFW_KEY_W)) app.camera.pitch = std::min(89.0f, app.camera.pitch + orbit), app.needsRedraw = true;
        if (ImGui::IsKeyDown(GLFW_KEY_S) && !io.KeyCtrl)
            app.camera.pitch = std::max(-89.0f, app.camera.pitch - orbit), app.needsRedraw = true;
        if (ImGui::IsKeyDown(GLFW_KEY_Q) && !io.KeyCtrl) app.camera.zoom(1 / zoom), app.needsRedraw = true;
        if (ImGui::IsKeyDown(GLFW_KEY_E) && !io.KeyCtrl) app.camera.zoom(zoom), app.needsRedraw = true;
        if (ImGui::IsKeyPressed(GLFW_KEY_P)) {
            const auto& s = kScreenshotSizes[app.view.screenshotSize];
            app.takeScreenshot(app.nextScreenshotPath(), s.width, s.height);
        }
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_F1)) app.showHelp = !app.showHelp;
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_S)) app.save();
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_O)) app.openPopup = true;
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_E) && !app.exportJob.running()) app.exportPopup = true;
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Q)) app.quitRequested = true;
}

}  // namespace sprout::viewer::detail
