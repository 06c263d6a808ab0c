#pragma once
// Grammar -> PNG-ready image with no display: derive, interpret, render through OSMesa.
// Used by `sprout render`, the screenshot tests and the no-display fallback of the viewer.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "app/image.hpp"
#include "app/render/camera.hpp"
#include "app/render/renderer.hpp"
#include "core/derive/derive.hpp"
#include "core/environment/environment_drawing.hpp"
#include "core/turtle/turtle.hpp"

namespace sprout {

struct SnapshotOptions {
    int width = 1280, height = 720;
    std::optional<int> iterations;       // default: the grammar's n
    std::optional<std::uint64_t> seed;   // default: the grammar's seed
    render::ViewPreset view = render::ViewPreset::Auto;
    std::optional<float> yaw, pitch;     // degrees, override the view preset
    // Where the camera looks and from how far (perspective views): a viewer screenshot's
    // zoom and pan. Default: framed on the plant.
    std::optional<float> distance;
    std::optional<glm::vec3> target;
    render::RenderOptions render;
    // Full detail, or the viewer's (`--detail viewer`: a big plant as the window shows it).
    bool viewerDetail = false;
    DeriveLimits limits;
    // Draw the environment the plant grew in (translucent shapes, obstacles, points, and a slice
    // of the light grid when asked): a grammar's own, or `environment` (a forest's).
    bool showEnvironment = false;
    EnvironmentView environmentView;
    std::shared_ptr<const Environment> environment;
    // A VLab object's view (Settings::picture): the camera when no view, yaw or pitch is given.
    std::optional<PictureView> picture;
};

// `o` made to show `picture` as cpfg would: its camera (snapshotCamera), its light and
// background, and its window's size unless `sizeGiven`.
void usePictureView(const PictureView& picture, SnapshotOptions& o, bool sizeGiven);
// The renderer's camera for a VLab object's view of `bounds`.
render::Camera pictureCamera(const PictureView& picture, const Bounds& bounds, float aspect);

struct Snapshot {
    Image image;
    Geometry geometry;
    render::RenderStats stats;
    double deriveMs = 0, interpretMs = 0, renderMs = 0;
};

// False with a message (derivation refused, no OpenGL, ...) on failure.
bool renderSnapshot(std::shared_ptr<const Grammar> grammar, const SnapshotOptions& options, Snapshot& out,
                    std::string& error);
// The camera a snapshot of `g` uses: framed on the plant, the options' view and angles.
render::Camera snapshotCamera(const Geometry& g, const SnapshotOptions& options);
// Renders `out.geometry` as it is (a forest scene, an imported model). `seed` places the
// environment's attraction points.
bool renderGeometry(const SnapshotOptions& options, Snapshot& out, std::string& error, std::uint64_t seed = 1);
// Makes the GL side of a picture of width x height ready on another thread (OSMesa loaded,
// its context made, the renderer's programs built and primed with `options`: Renderer::prime)
// while the caller reads and derives its plant: `sprout render` starts it first. The next
// renderGeometry of that size takes it.
void prepareSnapshot(int width, int height, const render::RenderOptions& options);
// Waits for that thread where it lives: the caller holds one while it may prepare, so that
// the thread ends before the program's exit handlers take OSMesa down under it.
struct PreparedSnapshotWait {
    PreparedSnapshotWait() = default;
    PreparedSnapshotWait(const PreparedSnapshotWait&) = delete;
    PreparedSnapshotWait& operator=(const PreparedSnapshotWait&) = delete;
    ~PreparedSnapshotWait();
};
// With options.showEnvironment, hands the environment drawn for `grown` to the renderer.
bool overlayEnvironment(render::Renderer& renderer, const SnapshotOptions& options, const Geometry& grown, std::uint64_t seed,
                        std::string& error);

}  // namespace sprout
