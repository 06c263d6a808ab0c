#include "app/viewer/state/worker.hpp"

#include <chrono>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include "app/plant/growth.hpp"
#include "app/plant/open.hpp"
#include "app/plant/scene.hpp"
#include "core/scene/forest.hpp"

namespace sprout::viewer {
namespace {
double millisSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

Worker::Worker() { m_thread = std::thread([this] { run(); }); }

Worker::~Worker() { stop(); }

void Worker::stop() {
    {
        // Under the lock: set between the worker's check of it and its sleep, the flag's
        // wake was lost, and the join below waited for ever.
        std::lock_guard lock(m_mutex);
        m_quit = true;
        m_cancel = true;
    }
    m_wake.notify_all();
    if (m_thread.joinable()) m_thread.join();
}

void Worker::post(Request request) {
    constexpr auto kDragKeep = std::chrono::milliseconds(250);  // a slower model's steps cancel, as any other edit
    std::lock_guard lock(m_mutex);
    m_latestPosted = request.generation;
    const bool sameDrag = request.gesture != 0 && m_busy && request.gesture == m_runningGesture &&
                          std::chrono::steady_clock::now() - m_runningSince < kDragKeep;
    m_pending = std::move(request);
    if (!sameDrag) m_cancel = true;  // whatever runs now is stale (a drag's step runs to its end: the plant follows)
    m_wake.notify_all();
}

bool Worker::working() const {
    std::lock_guard lock(m_mutex);
    return m_busy || m_pending || m_result;
}

void Worker::settle() {
    std::lock_guard lock(m_mutex);
    if (m_busy && m_pending) m_cancel = true;
}

void Worker::cancel() {
    std::lock_guard lock(m_mutex);
    m_pending.reset();
    m_cancel = true;
}

std::shared_ptr<const Result> Worker::take() {
    std::lock_guard lock(m_mutex);
    return std::exchange(m_result, nullptr);
}

std::shared_ptr<const Result> Worker::waitForResult(std::uint64_t generation) {
    std::unique_lock lock(m_mutex);
    m_done.wait(lock, [&] { return m_result && m_result->generation >= generation; });
    return std::exchange(m_result, nullptr);
}

void Worker::run() {
#ifdef __linux__
    // Below the window's thread (nice 10, this thread alone, and the threads it starts): on two
    // cores a derivation shares them with the frames, which waited for it. Dragging
    // lsystem9.lpy's curve, 9 runs each way: the longest of 30 frames within 17 ms in 6 runs
    // (4 at the same priority), the median frame 5-9 ms (6-11). A failure leaves it as it was.
    setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
#endif
    for (;;) {
        Request r;
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [&] { return m_quit || m_pending; });
            if (m_quit) return;
            r = std::move(*m_pending);
            m_pending.reset();
            m_cancel = false;
            m_busy = true;
            m_runningGesture = r.gesture;
            m_runningSince = std::chrono::steady_clock::now();
        }
        std::shared_ptr<Result> result = process(r);
        {
            std::lock_guard lock(m_mutex);
            m_busy = false;
            // A cancelled result is still reported when nothing newer is waiting, so the
            // window can say the work was dropped.
            if (!m_pending || !result->cancelled) m_result = result;
        }
        m_done.notify_all();
        if (finished) finished();
    }
}


std::shared_ptr<Result> Worker::processScene(const Request& r, std::shared_ptr<Result> out) {
    auto geometry = std::make_shared<Geometry>();
    auto t0 = std::chrono::steady_clock::now();
    auto source = speciesSource ? speciesSource : [](const std::string&) { return std::optional<std::string>(); };
    auto plants = std::make_shared<std::vector<ForestPlant>>();
    GrownScene grown = growScene(r.text, r.path, r.seed, source, limits, *geometry, plants.get());
    out->diagnostics = std::move(grown.diagnostics);
    if (!grown.parsed) return out;
    if (!grown.built) {
        out->message = grown.error;
        return out;
    }
    out->deriveMs = millisSince(t0);
    out->modules = grown.stats.segments;
    out->seed = grown.seed;
    out->environment = std::make_shared<const Environment>(std::move(grown.environment));
    out->forest = std::move(plants);
    if (prepare) out->prepared = prepare(geometry);
    out->geometry = std::move(geometry);
    return out;
}

std::shared_ptr<Result> Worker::processIfs(const Request& r, std::shared_ptr<Result> out) {
    // One thread: the other core keeps the window responsive.
    IfsPicture picture = drawIfs(r.text, r.seed, 1024, 768, 1, &m_cancel);
    out->diagnostics = std::move(picture.diagnostics);
    if (!picture.parsed) return out;
    if (!picture.drawn) {
        out->cancelled = true;
        return out;
    }
    out->deriveMs = picture.gameMs;
    out->modules = picture.points;
    out->seed = picture.seed;
    out->image = std::make_shared<const std::vector<std::uint8_t>>(std::move(picture.rgba));
    out->imageWidth = picture.width;
    out->imageHeight = picture.height;
    return out;
}

std::shared_ptr<Result> Worker::processLpy(const Request& r, std::shared_ptr<Result> out) {
    if (!r.python) {
        out->message = "this L-Py model's Python has not been run: trust it (the bar above the text) to run it";
        return out;
    }
    auto t0 = std::chrono::steady_clock::now();
    const int steps = r.iterations.value_or(-1);
    if (!m_lpy || r.text != m_lpyText || r.path != m_lpyPath || steps != m_lpySteps) {
        m_lpy.reset();
        lpy::RunOptions o;
        o.steps = steps;
        o.cancel = &m_cancel;
        o.keepSteps = true;
        o.drawLater = true;
        o.maxModules = std::size_t(std::min<std::uint64_t>(limits.maxModules, 50'000'000));
        std::shared_ptr<lpy::Model> model = openText(r.text, FileKind::Lpy, r.path, o).model;
        out->deriveMs = millisSince(t0);
        if (model->cancelled || m_cancel) {
            out->cancelled = true;
            return out;
        }
        m_lpy = std::move(model);
        const size_t kept = m_lpy->later ? size_t(m_lpy->later->steps()) : 0;
        m_lpyDrawn.assign(kept, nullptr);
        m_lpyFrom.assign(kept, nullptr);
        m_lpyText = r.text;
        m_lpyPath = r.path;
        m_lpySteps = steps;
    }
    out->diagnostics = m_lpy->diagnostics;
    if (!m_lpy->ok() || m_lpyDrawn.empty()) return out;  // the diagnostics say why
    const int n = int(m_lpyDrawn.size()) - 1;
    out->iterations = n;
    out->displayStep = r.displayStep < 0 ? n : std::min(r.displayStep, n);
    const std::size_t step = std::size_t(out->displayStep);
    if (!m_lpyDrawn[step]) {
        t0 = std::chrono::steady_clock::now();
        auto from = std::make_shared<std::vector<std::uint32_t>>();
        try {
            m_lpyDrawn[step] = m_lpy->later->draw(out->displayStep, from.get(), &m_cancel);
        } catch (lpy::DrawError& e) {  // a Python error in an interpretation rule, at its line
            out->diagnostics.push_back(e.diagnostic);
            return out;
        }
        if (!m_lpyDrawn[step]) {
            out->cancelled = true;
            return out;
        }
        m_lpyFrom[step] = std::move(from);
        out->deriveMs += millisSince(t0);
    }
    out->grammar = m_lpyDrawn[step];
    out->environment = std::shared_ptr<const Environment>(out->grammar, &out->grammar->environment);
    out->seed = r.seed.value_or(out->grammar->settings.seed);
    // The kept step is a grammar with no rules whose axiom is the string to draw.
    t0 = std::chrono::steady_clock::now();
    DeriveOptions opts;
    opts.limits = limits;
    opts.cancel = &m_cancel;
    opts.seed = out->seed;
    Growth d(out->grammar, opts);
    if (!d.derive(0).ok()) {
        out->cancelled = m_cancel;
        return out;
    }
    auto string = d.step(0);
    out->modules = string->size();
    auto geometry = std::make_shared<Geometry>();
    TurtleOptions t{0, out->seed, nullptr};
    // Picking: the model's run kept where each module came from (its rule and line).
    std::shared_ptr<PickData> pick;
    if (r.trackOrigins && step < m_lpy->record.steps.size() && m_lpyFrom[step]) {
        pick = std::make_shared<PickData>();
        t.segmentModules = &pick->segmentModules;
        t.surfaceModules = &pick->surfaceModules;
    }
    d.draw(0, t, *geometry);
    out->interpretMs = millisSince(t0);
    if (pick) {  // drawn modules -> the modules of the step that they draw
        const std::vector<std::uint32_t>& from = *m_lpyFrom[step];
        for (auto* list : {&pick->segmentModules, &pick->surfaceModules})
            for (std::uint32_t& k : *list) k = k < from.size() ? from[k] : 0;
        pick->record = m_lpy->record;
        pick->step = out->displayStep;
        out->pick = std::move(pick);
    }
    if (m_cancel) {
        out->cancelled = true;
        return out;
    }
    if (prepare) out->prepared = prepare(geometry);
    out->geometry = std::move(geometry);
    return out;
}

std::shared_ptr<Result> Worker::process(const Request& r) {
    auto out = std::make_shared<Result>();
    out->generation = r.generation;
    // Forest scenes and iterated function systems are opened in the same editor; what the
    // text is comes from core's detectFileKind, and a cpfg file stays cpfg while edited.
    const FileKind detected = detectFileKind("", r.text);
    const FileKind kind = detected == FileKind::Lsys && cpfgFamily(r.kind) ? r.kind : detected;
    if (kind == FileKind::Forest) return processScene(r, out);
    if (kind == FileKind::Ifs) return processIfs(r, out);
    if (kind == FileKind::Lpy && lpy::pythonAvailable()) return processLpy(r, out);
    auto t0 = std::chrono::steady_clock::now();
    if (r.text != m_cachedText || kind != m_cachedKind || r.path != m_cachedPath || r.filesVersion != m_cachedFilesVersion ||
        !m_cachedGrammar) {
        OpenedText parsed = openText(r.text, kind, r.path);
        m_cachedFilesVersion = r.filesVersion;
        m_cachedText = r.text;
        m_cachedKind = kind;
        m_cachedPath = r.path;
        m_cachedGrammar = parsed.grammar;
        m_cachedDiagnostics = std::move(parsed.diagnostics);
        m_growth.reset();
    }
    out->parseMs = millisSince(t0);
    out->diagnostics = m_cachedDiagnostics;
    out->grammar = m_cachedGrammar;
    if (!out->grammar) return out;
    out->environment = std::shared_ptr<const Environment>(out->grammar, &out->grammar->environment);

    const Grammar& g = *out->grammar;
    out->seed = r.seed.value_or(g.settings.seed);
    out->iterations = r.iterations.value_or(g.settings.iterations);
    out->displayStep = r.displayStep < 0 ? out->iterations : std::min(r.displayStep, out->iterations);
    if (!m_growth || m_cachedSeed != out->seed || m_cachedAges != r.trackAges || m_cachedOrigins != r.trackOrigins) {
        DeriveOptions opts;
        opts.seed = out->seed;
        opts.trackAges = r.trackAges;
        opts.trackOrigins = r.trackOrigins;
        m_cachedAges = r.trackAges;
        m_cachedOrigins = r.trackOrigins;
        opts.limits = limits;
        opts.cancel = &m_cancel;
        opts.progress = [this](int step, int, double fraction) {
            m_progressStep = step;
            m_progress = float(fraction);
        };
        m_growth = std::make_unique<Growth>(out->grammar, opts);
        m_cachedSeed = out->seed;
    }
    t0 = std::chrono::steady_clock::now();
    m_progress = 0;
    DeriveOutcome outcome = m_growth->grow(out->displayStep, limits);
    out->deriveMs = millisSince(t0);
    if (!outcome.ok()) {
        out->cancelled = outcome.status == DeriveStatus::Cancelled;
        out->message = outcome.message;
        if (outcome.status == DeriveStatus::TooBig) {
            // Said at the line that sets the derivation length, where the user lowers it (the
            // last good plant stays on screen, as for an error in the text).
            for (const auto& s : out->grammar->settingsRead)
                if (s.name == "n" || s.name == "iterations") {
                    out->diagnostics.push_back({s.line, 1, outcome.message, Severity::Error});
                    out->message.clear();
                }
        }
        if (out->cancelled) m_growth.reset();  // half-made: start again next time
        return out;
    }
    auto string = m_growth->step(out->displayStep);
    out->modules = string->size();
    if (m_cancel) {
        out->cancelled = true;
        return out;
    }
    t0 = std::chrono::steady_clock::now();
    auto geometry = std::make_shared<Geometry>();
    auto ages = m_growth->ages(out->displayStep);
    TurtleOptions t{out->displayStep, out->seed, ages ? ages->data() : nullptr};
    if (ages && r.growFraction < 1.0f) {
        t.growStep = out->displayStep;
        t.growFraction = std::max(0.0f, r.growFraction);
        out->growFraction = t.growFraction;
    }
    std::shared_ptr<PickData> pick;
    if (r.trackOrigins) {
        pick = std::make_shared<PickData>();
        t.segmentModules = &pick->segmentModules;
        t.surfaceModules = &pick->surfaceModules;
    }
    m_growth->draw(out->displayStep, t, *geometry);
    out->interpretMs = millisSince(t0);
    if (pick) {
        pick->record = DerivationRecord::of(m_growth->derivation());
        pick->step = out->displayStep;
        pick->homomorphism = !g.interpretation.productions.empty();
        out->pick = std::move(pick);
    }
    if (prepare) out->prepared = prepare(geometry);
    out->geometry = std::move(geometry);
    return out;
}

}  // namespace sprout::viewer
