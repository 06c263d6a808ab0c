// App's constructor and its actions (the panel, the keys and scripts call them): messages,
// files, the sun, the environment's drawing, framing, screenshots, model exports and videos.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <future>
#include <string>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "app/image.hpp"
#include "app/labels.hpp"
#include "app/snapshot.hpp"
#include "app/viewer/window/app.hpp"
#include "core/environment/environment_drawing.hpp"

namespace sprout::viewer {
namespace {

std::string cacheDir() {
    if (const char* c = std::getenv("XDG_CACHE_HOME"); c && *c) return std::string(c) + "/sprout/thumbnails";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/sprout/thumbnails";
    return "/tmp/sprout-thumbnails";
}

}  // namespace

App::App(std::string executable) : thumbnails(executable, cacheDir()), videoJob(executable) {
    const glm::vec3 d = glm::normalize(view.render.sunDirection);  // left as it is until a slider moves
    view.sunAzimuth = glm::degrees(std::atan2(d.x, d.z));
    view.sunElevation = glm::degrees(std::asin(d.y));
}

void App::recordVideo(const std::string& kind, const std::string& path) {
    auto plant = state.plant();
    std::string error;
    if (!plant || !plant->grammar || !plant->geometry)
        error = "videos are made of L-system plants (not of an IFS or a forest scene)";
    else if (videoJob.start(state.text(), kind, path, plant->iterations, plant->seed, 1280, 720, error))
        say("recording " + path + " ...");
    if (!error.empty()) say(error);
}

void App::exportModel(const std::string& path) {
    std::string error;
    auto plant = state.plant();
    if (plant && !plant->geometry) error = "this is an iterated function system: a picture, not a model (use a screenshot)";
    else if (exportJob.start(plant ? plant->geometry : nullptr, path, error)) say("exporting " + path + " ...");
    if (!error.empty()) say(error);
}

void App::say(std::string message) {
    status = std::move(message);
    statusTime = glfwGetTime();
}

void App::openFile(const std::string& path) {
    if (state.dirty()) state.autosave(true);  // never lose the edits
    std::string e;
    if (state.open(path, e)) {
        frameOnNextPlant = true;
        say("opened " + path);
    } else {
        say(e);
    }
}

void App::save() {
    std::string e;
    if (state.path().empty()) saveAsPopup = true;
    else if (!state.save(e)) say(e);
    else say("saved " + state.path().string());
}

void App::applySun() {
    float az = glm::radians(view.sunAzimuth), el = glm::radians(view.sunElevation);
    view.render.sunDirection = {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
    needsRedraw = true;
}

void App::updateEnvironment() {
    if (environmentJob.valid()) return;  // one at a time
    auto plant = state.plant();
    environmentOf = plant;
    environmentDirty = false;
    EnvironmentView how;
    how.lightSlice = view.lightSlice;
    how.sliceHeight = view.sliceHeight;
    const bool draw = plant && plant->geometry && plant->environment && !plant->environment->empty() && view.showEnvironment;
    environmentJob = std::async(draw ? std::launch::async : std::launch::deferred, [plant, how, draw] {
        EnvironmentDrawing d;
        d.plant = plant;
        if (draw && !drawEnvironment(*plant->environment, *plant->geometry, plant->seed, how, d.mesh, &d.error) && d.error.empty())
            d.error = "the environment could not be drawn";
        return d;
    });
}

void App::showEnvironment() {
    if (!environmentJob.valid() || renderer.uploading() ||
        environmentJob.wait_for(std::chrono::seconds(0)) == std::future_status::timeout)
        return;
    EnvironmentDrawing d = environmentJob.get();
    if (d.plant != state.plant()) return;  // the next drawing is for the plant now on screen
    if (!d.error.empty()) say(d.error);
    renderer.setOverlay(d.mesh);
    needsRedraw = true;
}

void App::frame() {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    const float aspect = float(std::max(1, w - panelWidth)) / float(std::max(1, h));
    auto plant = state.plant();
    if (plant && plant->geometry) {
        float yaw = camera.yaw, pitch = camera.pitch;
        bool keep = !frameOnNextPlant;
        camera = render::frameGeometry(*plant->geometry, aspect, render::ViewPreset::Auto);
        if (keep && !camera.orthographic) {  // re-frame, keep the direction the user chose
            camera.yaw = yaw;
            camera.pitch = pitch;
            camera = render::frameGeometry(*plant->geometry, aspect, render::ViewPreset::Auto);
            camera.yaw = yaw;
            camera.pitch = pitch;
        }
        // A VLab object's view: its camera, and its background and light in the view's options.
        const auto& picture = plant->grammar ? plant->grammar->settings.picture : std::nullopt;
        if (picture && !keep) {
            camera = pictureCamera(*picture, plant->geometry->bounds, aspect);
            SnapshotOptions o;
            o.render = view.render;
            usePictureView(*picture, o, true);
            view.render = o.render;
        }
    }
    needsRedraw = true;
}

void App::resetView() {
    frameOnNextPlant = true;
    frame();
    frameOnNextPlant = false;
}

std::string App::nextScreenshotPath() const {
    for (int i = 1;; ++i) {
        std::string p = "sprout-screenshot-" + std::to_string(i) + ".png";
        if (!std::filesystem::exists(p)) return p;
    }
}

bool App::takeScreenshot(const std::string& path, int width, int height) {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    if (width <= 0 || height <= 0) {
        width = std::max(16, w - panelWidth);
        height = std::max(16, h);
    }
    Image img;
    img.width = width;
    img.height = height;
    render::Camera cam = camera;
    auto plant = state.plant();
    if (plant && plant->image) {  // an iterated function system: its own image
        img.width = plant->imageWidth;
        img.height = plant->imageHeight;
        img.rgba = *plant->image;
        img.text.emplace_back("ifs", state.text());
        std::string error;
        bool ok = writePng(path, img, error);
        say(ok ? "saved " + path : path + ": " + error);
        return ok;
    }
    if (bigPlant && plant) {  // a picture gets full detail
        renderer.setDetail(render::Quality::Still);
        renderer.upload(*plant->geometry);
    }
    img.rgba = renderer.renderImage(cam, width, height, view.render);
    if (plant && plant->geometry) paintLabels(img, *plant->geometry, cam);
    if (bigPlant && plant) {
        if (plant->prepared) renderer.upload(*static_cast<const render::PreparedScene*>(plant->prepared.get()));
        else renderer.upload(*plant->geometry);
    }
    img.text.emplace_back("lsys", state.text());
    if (!cam.orthographic) {  // `sprout render FILE.png` looks from the same direction
        char view[200];  // and from where: the zoom and pan come back too
        std::snprintf(view, sizeof view, "--yaw %.2f --pitch %.2f --distance %.6g --target %.6g,%.6g,%.6g", double(cam.yaw),
                      double(cam.pitch), double(cam.distance), double(cam.target.x), double(cam.target.y), double(cam.target.z));
        img.text.emplace_back("sprout-view", view);
    }
    img.text.emplace_back("Software", "Sprout " SPROUT_VERSION);
    std::string error;
    bool ok = writePng(path, img, error);
    say(ok ? "saved " + path + " (" + std::to_string(width) + "x" + std::to_string(height) + ")" : path + ": " + error);
    needsRedraw = true;
    return ok;
}

}  // namespace sprout::viewer
