// The viewer's responsiveness, measured with the real ViewerState, worker and renderer
// (OSMesa, software GL), in one run:
//
//   build/bench/viewer_bench
//
// 1. Worst UI-thread frame while a 6.5 M-module derivation runs in the background: the
//    frame's own work (post the edit, poll the worker, animation, autosave, and the upload
//    of the plant when it arrives), against the 16 ms budget of a 60 Hz frame.
// 2. Keystroke to new plant on screen for a plant of about 100 k segments: edit, derive and
//    interpret on the worker, upload, draw the view (1010x860, interactive quality), finish.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "app/headless.hpp"
#include "app/render/renderer.hpp"
#include "app/viewer/state/viewer_state.hpp"

using namespace sprout;
using Clock = std::chrono::steady_clock;

static double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

int main() {
    const auto dir = std::filesystem::temp_directory_path() / "sprout_viewer_bench";
    // 1. Frames during a big derivation, and the frame in which the result arrives (its
    //    upload: the plant is baked on the worker, as in the window).
    {
        std::string error;
        auto ctx = HeadlessContext::create(64, 64, error);
        render::Renderer renderer;
        if (!ctx || !renderer.init(ctx->loader(), error)) {
            std::printf("no OpenGL: %s\n", error.c_str());
            return 1;
        }
        viewer::ViewerState state(dir);
        state.worker().prepare = [](const std::shared_ptr<const Geometry>& owner) -> std::shared_ptr<const void> {
        const Geometry& g = *owner;
            auto p = std::make_shared<render::PreparedScene>();
            render::Renderer::prepareForViewer(g, *p, owner);
            return p;
        };
        state.openText("n: 3\naxiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n");
        state.waitForPlant();
        double worst = 0, editMs = 0, arrivalMs = 0;
        int frames = 0;
        auto t0 = Clock::now();
        auto e0 = Clock::now();
        state.setText("n: 10\nangle: 22.5\naxiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n");  // 6.46 M modules
        editMs = ms(Clock::now() - e0);
        worst = editMs;
        // As the window does: the plant goes to the GPU a piece per frame (8 MB), the frames
        // go on until it is whole; every frame counts, the pieces' included.
        constexpr std::size_t kPiece = 8u << 20;
        bool arrivedOnce = false;
        int uploadFrames = 0;
        while (true) {
            auto f0 = Clock::now();
            bool arrived = state.update();
            if (arrived)
                renderer.beginUpload(std::static_pointer_cast<const render::PreparedScene>(state.plant()->prepared), kPiece);
            if (renderer.uploading()) {
                renderer.continueUpload(kPiece);
                ++uploadFrames;
            }
            state.tick(1.0 / 60);
            state.autosave();
            double f = ms(Clock::now() - f0);
            worst = std::max(worst, f);
            ++frames;
            if (arrived) arrivalMs = f;
            arrivedOnce |= arrived;
            if (arrivedOnce && !renderer.uploading()) break;
            std::this_thread::sleep_until(f0 + std::chrono::microseconds(16667));
        }
        double total = ms(Clock::now() - t0);
        std::printf("UI frames while deriving %s modules (%s segments; %.0f ms in the background): %d frames, worst %.2f ms "
                    "(the edit itself %.3f ms, the arrival frame %.2f ms, the upload in %d frames of 8 MB); budget 16 ms, "
                    "worst/budget %.2f\n",
                    withThousands(state.plant()->modules).c_str(), withThousands(state.plant()->geometry->cylinders.size()).c_str(),
                    total, frames, worst, editMs, arrivalMs, uploadFrames, worst / 16.0);
    }
    // 2. Keystroke to plant on screen.
    {
        const int w = 1010, h = 860;
        std::string error;
        auto ctx = HeadlessContext::create(w, h, error);
        render::Renderer renderer;
        if (!ctx || !renderer.init(ctx->loader(), error)) {
            std::printf("no OpenGL: %s\n", error.c_str());
            return 1;
        }
        renderer.setDetail(render::Quality::Interactive);  // as the window does for big plants
        viewer::ViewerState state(dir);
        // Fractal plant n=8: about 100 k segments.
        state.openText("n: 8\nangle: 22.5\naxiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n");
        state.waitForPlant();
        renderer.upload(*state.plant()->geometry);
        auto cam = render::frameGeometry(*state.plant()->geometry, float(w) / h, render::ViewPreset::Auto);
        render::RenderOptions o;
        o.quality = render::Quality::Interactive;
        renderer.draw(cam, w, h, o);  // warm up the shader compiler
        renderer.readPixels(1, 1);
        double best = 1e9, worst = 0, sum = 0, deriveSum = 0, uploadSum = 0, drawSum = 0;
        const int runs = 8;
        for (int i = 0; i < runs; ++i) {
            auto t0 = Clock::now();
            state.setDirectiveValue("angle", 20 + i);  // the keystroke
            state.waitForPlant();
            auto t1 = Clock::now();
            renderer.upload(*state.plant()->geometry);
            auto t2 = Clock::now();
            renderer.draw(cam, w, h, o);
            renderer.readPixels(1, 1);  // waits for the frame to be finished
            auto t3 = Clock::now();
            double total = ms(t3 - t0);
            best = std::min(best, total);
            worst = std::max(worst, total);
            sum += total;
            deriveSum += ms(t1 - t0);
            uploadSum += ms(t2 - t1);
            drawSum += ms(t3 - t2);
        }
        const auto& st = renderer.stats();
        std::printf("keystroke to plant on screen, %zu segments (%zu fine, %zu coarse, %zu prisms, %zu lines; %zu triangles), "
                    "%dx%d software GL: mean %.1f ms (best %.1f, worst %.1f); worker %.1f, upload %.1f, draw %.1f; "
                    "bar 50 ms, mean/bar %.2f\n",
                    state.plant()->geometry->cylinders.size(), st.levels[0], st.levels[1], st.levels[2], st.levels[3],
                    st.triangles, w, h, sum / runs, best, worst, deriveSum / runs, uploadSum / runs, drawSum / runs,
                    sum / runs / 50.0);
    }
    std::filesystem::remove_all(dir);
    return 0;
}
