#pragma once
// The viewer's background worker: parses, derives and interprets on its own thread, so the
// window never waits. Every request carries a generation; a newer request cancels the work
// in progress, and results come back as immutable shared values.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/plant/growth.hpp"
#include "core/derive/derive.hpp"
#include "core/language/file_kind.hpp"
#include "core/scene/forest.hpp"
#include "core/derive/provenance.hpp"
#include "core/turtle/turtle.hpp"
#include "lpy/lpy.hpp"

namespace sprout::viewer {

struct Request {
    std::string text;
    FileKind kind = FileKind::Lsys;  // what the open file is (the text is read as cpfg when it says so)
    std::string path;                // the open file, for cpfg #include; empty when untitled
    std::optional<int> iterations;        // default: the grammar's n
    int displayStep = -1;                 // the step to draw; -1: the last one
    std::optional<std::uint64_t> seed;    // default: the grammar's seed
    // Growth animation: modules created at the displayed step are drawn at this fraction of
    // their size (needs the derivation to record ages).
    float growFraction = 1.0f;
    bool trackAges = false;
    // Picking: keep where every module came from, and which module drew each segment.
    bool trackOrigins = false;
    // An L-Py model's Python may run (the user trusted it: app/viewer/state/trust.hpp).
    bool python = false;
    std::uint64_t generation = 0;
    // Counts the changes to the files beside the text that its parse reads (a VLab object's
    // functions and contours, edited in the panel): another count parses it again.
    std::uint64_t filesVersion = 0;
    // The drag this request is a step of (ViewerState::setText's gesture; 0: none). A step of
    // the drag whose step runs now does not cancel it (when it began less than kDragKeepMs
    // ago): it waits, so that the plant follows a point dragged faster than it derives.
    std::uint64_t gesture = 0;
};

// What a click needs to say which module drew a stem and which rule made it.
struct PickData {
    DerivationRecord record;                     // the steps and their origins
    int step = 0;                                // the step drawn
    std::vector<std::uint32_t> segmentModules;   // per segment: its module in the drawn string
    std::vector<std::uint32_t> surfaceModules;   // per leaf, petal, sphere
    bool homomorphism = false;                   // drawn through interpretation rules: indices are in their output
};

struct Result {
    std::uint64_t generation = 0;
    std::shared_ptr<const Grammar> grammar;  // null when the text has errors
    std::vector<Diagnostic> diagnostics;     // errors and warnings
    std::string message;                     // a refused or failed derivation
    bool cancelled = false;
    int iterations = 0, displayStep = 0;
    float growFraction = 1.0f;
    std::uint64_t seed = 0;
    std::shared_ptr<const Geometry> geometry;  // null unless the plant was made
    std::shared_ptr<const void> prepared;      // what Worker::prepare made of the geometry
    // The environment the plant grew in (a forest's shared one; a grammar's is in `grammar`).
    std::shared_ptr<const Environment> environment;
    std::shared_ptr<const PickData> pick;  // with Request::trackOrigins
    std::shared_ptr<const std::vector<ForestPlant>> forest;  // a forest scene: each plant's place in the geometry
    // An iterated function system is drawn as an image instead (RGBA, top row first).
    std::shared_ptr<const std::vector<std::uint8_t>> image;
    int imageWidth = 0, imageHeight = 0;
    std::uint64_t modules = 0;
    double parseMs = 0, deriveMs = 0, interpretMs = 0;
    bool ok() const { return geometry != nullptr || image != nullptr; }
};

class Worker {
public:
    Worker();
    ~Worker();
    Worker(const Worker&) = delete;
    Worker& operator=(const Worker&) = delete;

    // Replaces any pending request and cancels the one in progress. Never blocks.
    void post(Request request);
    // The newest finished result not yet taken, if any. Never blocks.
    std::shared_ptr<const Result> take();
    // For a progress bar: busy, and the fraction of the current step.
    bool busy() const { return m_busy.load(); }
    // Busy, a request waiting to be taken up or a result not yet taken: a plant is still to come.
    bool working() const;
    // A gesture's end: the step that runs is cancelled when a newer one waits (a drag's steps
    // otherwise run to their end so that the plant follows the point; now only the last counts).
    void settle();
    float progress() const { return m_progress.load(); }
    int progressStep() const { return m_progressStep.load(); }
    void cancel();
    // Cancels what runs and ends the worker's thread (its `finished` is not called after);
    // nothing posted after is taken up. The destructor does it too.
    void stop();
    // Blocks until the worker is idle and the result is available (tests, screenshots).
    std::shared_ptr<const Result> waitForResult(std::uint64_t generation);

    DeriveLimits limits;  // set before posting
    // Work for the worker after interpretation (the window bakes the plant for drawing here,
    // so a big plant's arrival costs the window only buffer copies); set before posting.
    // Given the geometry's owner: what it prepares may share it (a big planar curve is drawn
    // from the geometry's own segments).
    std::function<std::shared_ptr<const void>(const std::shared_ptr<const Geometry>&)> prepare;
    // Called on the worker's thread as each result is ready (the window wakes its event loop,
    // which waits while only the worker works); set before posting.
    std::function<void()> finished;
    // Where a forest scene's species come from (presets, files); set before posting.
    std::function<std::optional<std::string>(const std::string&)> speciesSource;

private:
    void run();
    std::shared_ptr<Result> process(const Request& r);
    std::shared_ptr<Result> processScene(const Request& r, std::shared_ptr<Result> out);
    std::shared_ptr<Result> processIfs(const Request& r, std::shared_ptr<Result> out);
    std::shared_ptr<Result> processLpy(const Request& r, std::shared_ptr<Result> out);

    mutable std::mutex m_mutex;
    std::condition_variable m_wake, m_done;
    std::optional<Request> m_pending;
    std::shared_ptr<const Result> m_result;
    std::atomic<bool> m_cancel{false}, m_busy{false}, m_quit{false};
    std::uint64_t m_runningGesture = 0;                   // under m_mutex
    std::chrono::steady_clock::time_point m_runningSince;  // under m_mutex
    std::atomic<float> m_progress{0};
    std::atomic<int> m_progressStep{0};
    std::uint64_t m_latestPosted = 0;

    // Derivation cache: re-deriving the same text and seed with another n or display step
    // reuses the steps already made (stepping through iterations costs nothing extra).
    std::string m_cachedText;
    FileKind m_cachedKind = FileKind::Lsys;
    std::string m_cachedPath;
    std::uint64_t m_cachedFilesVersion = 0;
    std::uint64_t m_cachedSeed = 0;
    bool m_cachedAges = false;
    bool m_cachedOrigins = false;
    std::shared_ptr<const Grammar> m_cachedGrammar;
    std::vector<Diagnostic> m_cachedDiagnostics;
    std::unique_ptr<Growth> m_growth;
    // An L-Py model run by Python (lpy/lpy.hpp), every step kept: stepping through it draws
    // the kept steps, and only a change of text, file or length runs the Python again. A
    // step's drawing (its interpretation rules, its shapes) is made when it is first shown.
    std::shared_ptr<const lpy::Model> m_lpy;
    std::vector<std::shared_ptr<const Grammar>> m_lpyDrawn;
    std::vector<std::shared_ptr<const std::vector<std::uint32_t>>> m_lpyFrom;
    std::string m_lpyText, m_lpyPath;
    int m_lpySteps = -1;
    // Last: the thread starts once every member it uses exists.
    std::thread m_thread;
};

}  // namespace sprout::viewer
