#include "app/snapshot.hpp"

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include <glm/geometric.hpp>

#include "app/headless.hpp"
#include "app/plant/growth.hpp"

namespace sprout {
namespace {
double millisSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// prepareSnapshot's context and renderer, made on their own thread (loading OSMesa and LLVM
// and building the programs take tens of milliseconds: an L-Py model's Python starts in as
// many). Whoever takes them joins the thread first; PreparedSnapshotWait lets go of them
// when no picture took them (the model failed).
struct Prepared {
    std::mutex mutex;
    std::thread thread;
    std::atomic<bool> wanted{false};  // taken, or no longer needed: the thread stops priming
    int width = 0, height = 0;
    std::unique_ptr<HeadlessContext> context;
    std::unique_ptr<render::Renderer> renderer;

    ~Prepared() {  // PreparedSnapshotWait has let them go; at exit, no GL calls are made
        if (thread.joinable()) thread.join();
        (void)renderer.release();
        (void)context.release();
    }
    // The context and renderer for a picture of this size, current on this thread; false
    // when none was prepared for it (or it failed: the caller makes its own and says why).
    bool take(int w, int h, std::unique_ptr<HeadlessContext>& c, std::unique_ptr<render::Renderer>& r) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!thread.joinable() || w != width || h != height) return false;
        wanted = true;
        thread.join();
        if (!context || !renderer || !context->makeCurrent()) return false;
        c = std::move(context);
        r = std::move(renderer);
        return true;
    }
};

Prepared& prepared() {
    static Prepared p;
    return p;
}
}  // namespace

PreparedSnapshotWait::~PreparedSnapshotWait() {
    Prepared& p = prepared();
    std::lock_guard<std::mutex> lock(p.mutex);
    p.wanted = true;
    if (p.thread.joinable()) p.thread.join();
    if (!p.context) return;  // taken, or never made
    if (p.context->makeCurrent()) p.renderer.reset();  // its GL objects in their context
    else (void)p.renderer.release();
    p.context.reset();
}

void prepareSnapshot(int width, int height, const render::RenderOptions& options) {
    Prepared& p = prepared();
    std::lock_guard<std::mutex> lock(p.mutex);
    if (p.thread.joinable() || p.context) return;  // once
    p.width = width;
    p.height = height;
    p.thread = std::thread([&p, width, height, options] {
        std::string error;
        auto context = HeadlessContext::create(width, height, error);
        if (!context) return;
        auto renderer = std::make_unique<render::Renderer>();
        if (!renderer->init(context->loader(), error)) return;
        renderer->prime(width, height, options, p.wanted);
        HeadlessContext::release();  // for the thread that draws
        p.context = std::move(context);
        p.renderer = std::move(renderer);
    });
}

bool renderSnapshot(std::shared_ptr<const Grammar> grammar, const SnapshotOptions& o, Snapshot& out,
                    std::string& error) {
    auto t0 = std::chrono::steady_clock::now();
    const int n = o.iterations.value_or(grammar->settings.iterations);
    DeriveOptions dopts;
    dopts.seed = o.seed;
    dopts.limits = o.limits;
    Growth growth(grammar, dopts);
    DeriveOutcome outcome = growth.grow(n, o.limits);
    if (!outcome.ok()) {
        error = outcome.message;
        return false;
    }
    out.deriveMs = millisSince(t0);

    t0 = std::chrono::steady_clock::now();
    growth.draw(n, {n, growth.seed(), nullptr}, out.geometry);
    out.interpretMs = millisSince(t0);
    if (o.showEnvironment && !o.environment) {
        SnapshotOptions own = o;
        own.environment = std::shared_ptr<const Environment>(grammar, &grammar->environment);
        return renderGeometry(own, out, error, growth.seed());
    }
    return renderGeometry(o, out, error, growth.seed());
}

bool overlayEnvironment(render::Renderer& renderer, const SnapshotOptions& o, const Geometry& grown, std::uint64_t seed,
                        std::string& error) {
    if (!o.showEnvironment || !o.environment || o.environment->empty()) return true;
    Mesh mesh;
    if (!drawEnvironment(*o.environment, grown, seed, o.environmentView, mesh, &error)) return false;
    renderer.setOverlay(mesh);
    return true;
}

render::Camera pictureCamera(const PictureView& p, const Bounds& bounds, float aspect) {
    auto vec = [](const std::array<double, 3>& a) { return glm::vec3(float(a[0]), float(a[1]), float(a[2])); };
    render::ViewDirection v;
    v.eye = vec(p.eye);
    v.target = vec(p.target);
    v.roll = float(p.twist);
    v.perspective = p.perspective;
    v.fovY = float(p.viewingAngle);
    v.scale = float(p.scale);
    return render::frameView(bounds, aspect, v);
}

void usePictureView(const PictureView& p, SnapshotOptions& o, bool sizeGiven) {
    o.picture = p;
    if (!sizeGiven && p.width > 0 && p.height > 0) {
        o.width = p.width;
        o.height = p.height;
    }
    if (p.background) {
        const glm::vec3 c(float(*p.background >> 16 & 0xFF) / 255.0f, float(*p.background >> 8 & 0xFF) / 255.0f,
                          float(*p.background & 0xFF) / 255.0f);
        o.render.backgroundTop = o.render.backgroundBottom = c;
        o.render.ground = false;  // cpfg's window: the plant on its background
    }
    if (p.ink)
        o.render.curveInk = glm::vec3(float(*p.ink >> 16 & 0xFF) / 255.0f, float(*p.ink >> 8 & 0xFF) / 255.0f, float(*p.ink & 0xFF) / 255.0f);
    const glm::vec3 light(float(p.light[0]), float(p.light[1]), float(p.light[2]));
    if (glm::length(light) > 0) o.render.sunDirection = glm::normalize(light);
}

render::Camera snapshotCamera(const Geometry& g, const SnapshotOptions& o) {
    const float aspect = float(o.width) / float(o.height);
    if (o.picture && !o.yaw && !o.pitch && o.view == render::ViewPreset::Auto) {
        render::Camera camera = pictureCamera(*o.picture, g.bounds, aspect);
        if (o.distance) camera.distance = *o.distance;
        if (o.target) camera.target = *o.target;
        return camera;
    }
    render::Camera camera = render::frameGeometry(g, aspect, o.view);
    if (o.yaw || o.pitch) {
        // An explicit direction: keep the framing distance of a 3D view.
        render::Camera c3 = render::frameBounds(g.bounds, aspect, render::ViewPreset::Iso, false);
        camera.orthographic = g.planarCurve && camera.orthographic;
        if (!camera.orthographic) camera.distance = c3.distance;
        camera.yaw = o.yaw.value_or(camera.yaw);
        camera.pitch = o.pitch.value_or(camera.pitch);
    }
    if (!camera.orthographic) {
        if (o.distance) camera.distance = *o.distance;
        if (o.target) camera.target = *o.target;
    }
    return camera;
}

bool renderGeometry(const SnapshotOptions& o, Snapshot& out, std::string& error, std::uint64_t seed) {
    auto t0 = std::chrono::steady_clock::now();
    std::unique_ptr<HeadlessContext> context;
    std::unique_ptr<render::Renderer> made;
    if (!prepared().take(o.width, o.height, context, made)) {
        context = HeadlessContext::create(o.width, o.height, error);
        if (!context) return false;
        made = std::make_unique<render::Renderer>();
        if (!made->init(context->loader(), error)) return false;
    }
    render::Renderer& renderer = *made;
    if (o.viewerDetail) renderer.setDetail(render::viewerDetail(out.geometry.cylinders.size()));
    renderer.upload(out.geometry);
    if (!overlayEnvironment(renderer, o, out.geometry, seed, error)) return false;
    render::Camera camera = snapshotCamera(out.geometry, o);
    render::RenderOptions options = o.render;
    options.quickLines = o.viewerDetail && renderer.software();  // the viewer's view, as it draws it
    renderer.draw(camera, o.width, o.height, options, 0);
    out.image.width = o.width;
    out.image.height = o.height;
    out.image.rgba = renderer.readPixels(o.width, o.height, 0);
    out.stats = renderer.stats();
    out.renderMs = millisSince(t0);
    return true;
}

}  // namespace sprout
