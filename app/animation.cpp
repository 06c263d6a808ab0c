#include "app/animation.hpp"

#include "core/base/atomic_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app/headless.hpp"
#include "app/plant/growth.hpp"
#include "core/derive/derive.hpp"
#include "core/turtle/turtle.hpp"

namespace sprout {
namespace {

bool endsWith(const std::string& s, const char* ext) {
    std::string e(ext);
    if (s.size() < e.size()) return false;
    for (size_t i = 0; i < e.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(s[s.size() - e.size() + i])) != e[i]) return false;
    return true;
}

// Where frames go: ffmpeg's standard input, or numbered PNG files.
class FrameSink {
public:
    ~FrameSink() { finish(false); }  // not finished on purpose: an error, the old video stays
    bool open(const std::string& out, int w, int h, int fps, bool video, std::string& error) {
        m_out = out;
        m_w = w, m_h = h;
        if (!video) return true;
        // ffmpeg writes a unique temporary beside the real file (links followed), renamed over
        // it only when the video is whole: a failure keeps the old video.
        if (!resolveLinks(out, m_target, error)) return false;
        const size_t slash = m_target.find_last_of('/'), dot = m_target.find_last_of('.');
        const std::string dir = slash == std::string::npos ? "." : m_target.substr(0, slash);
        const std::string name = m_target.substr(slash == std::string::npos ? 0 : slash + 1);
        const std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : m_target.substr(dot);
        std::string tmpl = dir + "/." + name + ".sprout-XXXXXX" + ext;
        std::vector<char> buf(tmpl.begin(), tmpl.end());
        buf.push_back('\0');
        const int tfd = mkstemps(buf.data(), int(ext.size()));
        if (tfd < 0) {
            error = std::string("cannot write: ") + std::strerror(errno);
            return false;
        }
        (void)::fchmod(tfd, mode_t(newFileMode(m_target)));
        ::close(tfd);
        m_temp = buf.data();
        int fds[2];
        if (pipe(fds) != 0) {
            error = std::string("cannot start ffmpeg: ") + std::strerror(errno);
            return false;
        }
        const std::string size = std::to_string(w) + "x" + std::to_string(h), rate = std::to_string(fps);
        m_pid = fork();
        if (m_pid == 0) {
            dup2(fds[0], 0);
            close(fds[0]);
            close(fds[1]);
            const char* argv[] = {"ffmpeg", "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "rgba", "-s", size.c_str(),
                                  "-r", rate.c_str(), "-i", "-", "-c:v", "libx264", "-preset", "medium", "-crf", "20",
                                  "-pix_fmt", "yuv420p", "-movflags", "+faststart", m_temp.c_str(), nullptr};
            execvp("ffmpeg", const_cast<char* const*>(argv));
            _exit(127);
        }
        close(fds[0]);
        if (m_pid < 0) {
            close(fds[1]);
            error = std::string("cannot start ffmpeg: ") + std::strerror(errno);
            return false;
        }
        m_pipe = fds[1];
        std::signal(SIGPIPE, SIG_IGN);  // ffmpeg failing must not kill us
        return true;
    }
    bool write(const Image& frame, int index, std::string& error) {
        if (m_pipe < 0) {
            char name[32];
            std::snprintf(name, sizeof name, "_%04d.png", index + 1);
            std::string path = m_out.substr(0, m_out.size() - 4) + name;
            if (index == 0) m_first = path;
            if (!writePng(path, frame, error)) {
                error = path + ": " + error;
                return false;
            }
            return true;
        }
        const char* p = reinterpret_cast<const char*>(frame.rgba.data());
        size_t left = frame.rgba.size();
        while (left > 0) {
            ssize_t n = ::write(m_pipe, p, left);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                error = "ffmpeg stopped taking frames (" + m_out + ": see its message above)";
                return false;
            }
            p += n, left -= size_t(n);
        }
        return true;
    }
    // Waits for ffmpeg; false when it failed. The video replaces the target only when whole.
    bool finish(bool keep = true) {
        if (m_pipe >= 0) close(m_pipe), m_pipe = -1;
        if (m_pid <= 0) return true;
        int status = 0;
        waitpid(m_pid, &status, 0);
        m_pid = -1;
        const bool ok = keep && WIFEXITED(status) && WEXITSTATUS(status) == 0 && ::rename(m_temp.c_str(), m_target.c_str()) == 0;
        if (!ok) ::unlink(m_temp.c_str());
        m_temp.clear();
        return ok;
    }
    const std::string& first() const { return m_first; }

private:
    std::string m_out, m_first, m_target, m_temp;
    int m_w = 0, m_h = 0, m_pipe = -1;
    pid_t m_pid = -1;
};

}  // namespace

bool haveFfmpeg() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

bool renderAnimation(std::shared_ptr<const Grammar> grammar, const SnapshotOptions& so, const AnimationOptions& ao,
                     const std::string& out, AnimationResult& result, std::string& error) {
    const bool wantsVideo = endsWith(out, ".mp4") || endsWith(out, ".mkv") || endsWith(out, ".webm") || endsWith(out, ".mov");
    if (!wantsVideo && !endsWith(out, ".png")) {
        error = "an animation is written as .mp4 (or .mkv, .webm, .mov) or as a numbered .png sequence";
        return false;
    }
    result = {};
    result.video = wantsVideo && haveFfmpeg();
    if (wantsVideo && !result.video) result.note = "ffmpeg is not installed (apt-get install ffmpeg): wrote PNG frames instead";
    SnapshotOptions o = so;
    if (result.video) {  // H.264 in 4:2:0 wants even sizes
        o.width &= ~1;
        o.height &= ~1;
    }
    const std::string target = wantsVideo && !result.video ? out.substr(0, out.find_last_of('.')) + ".png" : out;

    const bool kept = !ao.steps.empty();
    const bool shown = !kept && ao.kind == AnimationKind::Growth && !ao.shownSteps.empty();
    const int n = kept ? int(ao.steps.size()) - 1
                  : shown ? *std::max_element(ao.shownSteps.begin(), ao.shownSteps.end())
                          : o.iterations.value_or(grammar->settings.iterations);
    DeriveOptions dopts;
    dopts.seed = o.seed;
    dopts.limits = o.limits;
    dopts.trackAges = ao.kind == AnimationKind::Growth;
    Growth growth(grammar, dopts);
    DeriveOutcome outcome = growth.derive(kept ? 0 : n);
    if (!outcome.ok()) {
        error = outcome.message;
        return false;
    }
    const int frames = shown ? int(ao.shownSteps.size())
                       : ao.frames > 0 ? ao.frames
                       : ao.kind == AnimationKind::Growth ? std::max(2, n * ao.fps / 2 + 1)
                                                          : ao.fps * 5;
    auto context = HeadlessContext::create(o.width, o.height, error);
    if (!context) return false;
    render::Renderer renderer;
    if (!renderer.init(context->loader(), error)) return false;

    // The camera stays where the grown plant is framed.
    Geometry geometry;
    auto interpretStep = [&](int step, float fraction) {
        if (kept) {  // a kept step is drawn as it is
            const Grammar& g = *ao.steps[size_t(step)];
            TurtleOptions t{0, growth.seed(), nullptr};
            drawAsIs(g.axiom, g, t, geometry);
            return;
        }
        auto ages = growth.ages(step);
        TurtleOptions t{step, growth.seed(), ages ? ages->data() : nullptr};
        if (ages && fraction < 1.0f) {
            t.growStep = step;
            t.growFraction = fraction;
        }
        growth.draw(step, t, geometry);
    };
    interpretStep(n, 1.0f);
    const render::Camera framed = snapshotCamera(geometry, o);
    const Bounds grown = geometry.bounds;  // ground and shadows sized for the grown plant
    const bool planar = geometry.planarCurve;
    SnapshotOptions withEnvironment = o;  // a grammar's own environment, drawn when asked
    if (o.showEnvironment && !o.environment) withEnvironment.environment = std::shared_ptr<const Environment>(grammar, &grammar->environment);
    if (ao.kind == AnimationKind::Turntable) {
        renderer.upload(geometry);
        if (!overlayEnvironment(renderer, withEnvironment, geometry, growth.seed(), error)) return false;
    }

    FrameSink sink;
    if (!sink.open(target, o.width, o.height, ao.fps, result.video, error)) return false;
    Image frame;
    frame.width = o.width;
    frame.height = o.height;
    if (!result.video) frame.text.emplace_back("lsys", ao.recipe);
    for (int k = 0; k < frames; ++k) {
        render::Camera camera = framed;
        if (ao.kind == AnimationKind::Growth) {
            // Time runs from the axiom (step 0) to step n; within a step its new segments grow in.
            double t = frames > 1 ? double(n) * k / (frames - 1) : n;
            int step = shown ? ao.shownSteps[size_t(k)] : int(std::ceil(t - 1e-9));
            float fraction = shown || step == 0 ? 1.0f : float(1.0 - (step - t));
            interpretStep(step, std::clamp(fraction, 0.0f, 1.0f));
            geometry.bounds = grown;
            geometry.planarCurve = planar;  // an axiom that draws nothing is no 2D curve
            renderer.upload(geometry);
            // The environment as the plant at this frame sees it (points used up, its shade).
            if (!overlayEnvironment(renderer, withEnvironment, geometry, growth.seed(), error)) return false;
        } else {
            camera.yaw = framed.yaw + 360.0f * float(k) / float(frames);
        }
        renderer.draw(camera, o.width, o.height, o.render, 0);
        frame.rgba = renderer.readPixels(o.width, o.height, 0);
        if (!sink.write(frame, k, error)) return false;
        if (ao.progress) ao.progress(k + 1, frames);
    }
    if (!sink.finish()) {
        error = "ffmpeg failed to write " + out;
        return false;
    }
    result.frames = frames;
    result.firstFrame = sink.first();
    return true;
}

}  // namespace sprout
