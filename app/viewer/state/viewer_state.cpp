#include "app/viewer/state/viewer_state.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>
#include <utility>

#include "app/plant/text_edit.hpp"
#include "app/plant/vlab_view.hpp"
#include "core/base/read_file.hpp"
#include "lpy/lpy.hpp"
#include "core/language/import/import.hpp"
#include "core/base/atomic_file.hpp"

namespace sprout::viewer {
namespace fs = std::filesystem;

bool saveTextAtomically(const fs::path& path, const std::string& text, std::string& error) {
    // A unique temporary beside the real file (a symlinked grammar updates the file it names),
    // fsync, rename, fsync of the folder (core/base/atomic_file.hpp).
    return writeFileAtomically(path.string(), text, error);
}

namespace {

fs::path defaultAutosaveDir() {
    if (const char* s = std::getenv("XDG_STATE_HOME"); s && *s) return fs::path(s) / "sprout";
    if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".local" / "state" / "sprout";
    return fs::temp_directory_path() / "sprout";
}

}  // namespace

ViewerState::ViewerState(fs::path autosaveDir, fs::path trustFile)
    : m_autosaveDir(autosaveDir.empty() ? defaultAutosaveDir() : autosaveDir),
      m_trustStore(!trustFile.empty() ? trustFile : autosaveDir.empty() ? fs::path() : autosaveDir / "trusted-models") {
    std::error_code ec;
    fs::create_directories(m_autosaveDir, ec);
    // A session marker: present at start means the last session did not end cleanly.
    const fs::path marker = m_autosaveDir / "session";
    m_crashedBefore = fs::exists(marker, ec);
    std::ofstream(marker) << ::getpid() << "\n";
    if (m_crashedBefore) {
        // Kept in memory (and in a copy on disk) before this session's first autosave
        // overwrites the file: the offer to recover must find the old text.
        m_recovered = readFile(m_autosaveDir / "autosave.lsys").value_or("");
        if (!m_recovered.empty()) fs::copy_file(m_autosaveDir / "autosave.lsys", m_autosaveDir / "previous-session.lsys",
                                                fs::copy_options::overwrite_existing, ec);
    }
}

ViewerState::~ViewerState() = default;

void ViewerState::post(std::uint64_t gesture) {
    Request r;
    r.text = m_text;
    r.kind = m_kind;
    r.path = m_path.string();
    r.seed = m_seedOverride;
    r.displayStep = m_displayStep;
    r.trackAges = m_playing && smoothGrowth;
    r.growFraction = r.trackAges ? m_growFraction : 1.0f;
    r.trackOrigins = m_picking;
    r.python = m_trust == TrustAnswer::Trusted;
    r.generation = ++m_generation;
    r.filesVersion = m_filesVersion;
    r.gesture = gesture;
    m_worker.post(std::move(r));
}

bool ViewerState::pythonBlocked() const {
    return m_kind == FileKind::Lpy && lpy::pythonAvailable() && m_trust != TrustAnswer::Trusted;
}

void ViewerState::lookUpTrust() {
    // Only an L-Py text asks; any other kind keeps no answer (it has no Python to run).
    m_trust = detectFileKind("", m_text) == FileKind::Lpy ? m_trustStore.answer(m_text) : TrustAnswer::Trusted;
}

void ViewerState::answerTrust(bool trusted) {
    m_trust = trusted ? TrustAnswer::Trusted : TrustAnswer::Refused;
    std::string error;
    m_trustStore.remember(m_text, m_trust, error);  // unkept, the answer holds for this session
    post();
}

void ViewerState::restoreRecovered() {
    if (auto text = recoverable()) {
        m_text = std::move(*text);
        m_dirty = true;
        m_kind = detectFileKind("", m_text);
        if (m_kind != FileKind::Ifs && m_kind != FileKind::Forest && !cpfgFamily(m_kind)) m_kind = FileKind::Lsys;
        lookUpTrust();
        post();
    }
    discardRecovery();
}

void ViewerState::setPicking(bool on) {
    if (on == m_picking) return;
    m_picking = on;
    post();
}

void ViewerState::filesChanged() {
    ++m_filesVersion;
    post();
}

void ViewerState::setText(std::string text, std::uint64_t gesture) {
    if (text == m_text) return;
    m_text = std::move(text);
    m_textGesture = gesture;
    m_dirty = true;
    post(gesture);
}

void ViewerState::setDirectiveValue(const std::string& key, double value) {
    setText(setDirective(m_text, key, formatValue(value)));
}

void ViewerState::setDefineValue(const std::string& name, double value) {
    setText(setDefine(m_text, name, formatValue(value)));
}

void ViewerState::setIterations(int n) {
    m_displayStep = -1;
    // L-Py's is `derivation length:` (a line `n:` would be Python there).
    setText(setDirective(m_text, m_kind == FileKind::Lpy ? "derivation length" : "n", std::to_string(std::max(0, n))));
}

void ViewerState::setSeed(std::uint64_t seed) { setText(setDirective(m_text, "seed", std::to_string(seed))); }

void ViewerState::newSpecimen() {
    std::uint64_t current = m_plant && m_plant->grammar ? m_plant->seed : 1;
    // A different seed each time, reproducible from the text.
    setSeed((current * 6364136223846793005ull + 1442695040888963407ull) % 1000000007ull);
}

void ViewerState::setDisplayStep(int step) {
    int n = m_plant ? m_plant->iterations : 0;
    step = std::clamp(step, 0, std::max(n, 0));
    int current = m_displayStep < 0 ? n : m_displayStep;
    if (step == current) return;
    m_displayStep = step == n ? -1 : step;
    post();
}

void ViewerState::stepBy(int delta) {
    int n = m_plant ? m_plant->iterations : 0;
    setDisplayStep((m_displayStep < 0 ? n : m_displayStep) + delta);
}

void ViewerState::setPlaying(bool on) {
    m_playing = on;
    m_animClock = 0;
    m_growFraction = on && smoothGrowth ? 0.0f : 1.0f;
    if (on && m_plant && (m_displayStep < 0 || m_displayStep >= m_plant->iterations)) {
        m_displayStep = -1;
        setDisplayStep(0);
    } else {
        post();
    }
}

void ViewerState::tick(double seconds) {
    if (!m_playing || !m_plant) return;
    if (m_worker.busy()) return;  // wait for the frame on screen before moving on
    m_animClock += seconds;
    const double period = 1.0 / std::max(0.05f, stepsPerSecond);
    const int n = m_plant->iterations;
    const int current = m_displayStep < 0 ? n : m_displayStep;
    if (m_animClock < period) {
        if (smoothGrowth) {  // the step's new segments grow in
            m_growFraction = float(m_animClock / period);
            post();
        }
        return;
    }
    m_animClock = 0;
    m_growFraction = smoothGrowth ? 0.0f : 1.0f;
    if (current >= n) {
        if (loop) {
            setDisplayStep(0);
        } else {
            m_playing = false;
            m_growFraction = 1.0f;
            post();
        }
    } else {
        setDisplayStep(current + 1);
    }
}

bool ViewerState::update() {
    auto r = m_worker.take();
    if (!r) return false;
    m_latest = r;
    if (r->ok()) {
        m_plant = r;
        return true;
    }
    return false;
}

void ViewerState::waitForPlant() {
    auto r = m_worker.waitForResult(m_generation);
    if (!r) return;
    m_latest = r;
    if (r->ok()) m_plant = r;
}

bool ViewerState::open(const fs::path& given, std::string& error, const std::string& system) {
    // A VLab object: its L-system opens, and the object is kept for the panel.
    fs::path path = given;
    std::optional<VlabSummary> object;
    if (std::optional<VlabObject> o = vlabObjectAt(given.string())) {
        for (const Diagnostic& d : o->diagnostics)
            if (d.severity == Severity::Error && fs::is_directory(given)) {  // a file in it still opens as it is
                error = formatDiagnostic(d, o->specifications);
                return false;
            }
        if (!hasErrors(o->diagnostics)) {
            path = o->lsystem;
            object = summarizeVlabObject(*o);
        }
    }
    if (!openFile(path, error, system)) return false;
    m_vlab = std::move(object);
    if (m_vlab && m_vlab->animate) {  // cpfg -a: the animation file's frames play from its first
        setDisplayStep(0);
        setPlaying(true);
    }
    return true;
}

bool ViewerState::openFile(const fs::path& path, std::string& error, const std::string& system) {
    auto text = readFile(path);
    if (!text) {
        error = "cannot open " + path.string() + ": " + std::strerror(errno);
        return false;
    }
    // One way in (core's importFile): what the file is comes from its content. .lsys and
    // cpfg-family files open as written and save back in their own syntax; Lparser and
    // Fractint files open as the .lsys they translate to; a PNG as the text it carries.
    ImportResult imported = importFile(path.string(), *text, system);
    if (!imported.ok()) {
        const Diagnostic& d = imported.diagnostics.front();
        error = path.string() + ":" + std::to_string(d.line) + ":" + std::to_string(d.col) + ": " + d.message;
        return false;
    }
    if (imported.text == *text && imported.source != FileKind::Png) {
        openText(std::move(*text), path);
        if (std::exchange(m_kind, imported.kind) != imported.kind) post();
        return true;
    }
    openText(std::move(imported.text));  // no path: saving asks for a name
    if (std::exchange(m_kind, imported.kind) != imported.kind) post();
    m_importedFrom = path;
    m_importSystems.clear();
    if (imported.source == FileKind::Fractint)
        for (const auto& s : listFractint(*text)) m_importSystems.push_back(s.name);
    return true;
}

void ViewerState::openText(std::string text, fs::path path, std::string preset) {
    m_path = std::move(path);
    m_preset = std::move(preset);
    m_vlab.reset();
    m_importedFrom.clear();
    m_importSystems.clear();
    std::error_code ec;
    m_fileTime = m_path.empty() ? fs::file_time_type{} : fs::last_write_time(m_path, ec);
    m_displayStep = -1;
    m_seedOverride.reset();
    m_text = std::move(text);
    m_kind = detectFileKind("", m_text);
    if (m_kind != FileKind::Ifs && m_kind != FileKind::Forest && !cpfgFamily(m_kind)) m_kind = FileKind::Lsys;
    m_dirty = false;
    if (m_preset.empty()) lookUpTrust();  // a file, a PNG, an import: from outside
    else m_trust = TrustAnswer::Trusted;  // Sprout's own
    post();
}

std::string ViewerState::title() const {
    if (!m_path.empty()) return m_path.filename().string();
    if (!m_preset.empty()) return m_preset + " (preset)";
    return "untitled";
}

bool ViewerState::save(std::string& error) {
    if (m_path.empty()) {
        error = "no file name yet: use Save as";
        return false;
    }
    return saveAs(m_path, error);
}

bool ViewerState::saveAs(const fs::path& path, std::string& error) {
    if (!saveTextAtomically(path, m_text, error)) {
        error = "could not save " + path.string() + ": " + error + " (the old file is unchanged)";
        return false;
    }
    m_path = path;
    std::error_code ec;
    m_fileTime = fs::last_write_time(m_path, ec);
    m_dirty = false;
    // What the user saves from a model they trust (or typed) opens again without asking.
    if (m_trust == TrustAnswer::Trusted && m_kind == FileKind::Lpy) m_trustStore.remember(m_text, m_trust, error);
    error.clear();
    return true;
}

bool ViewerState::reloadIfChangedOnDisk() {
    if (m_path.empty() || m_dirty) return false;
    std::error_code ec;
    auto t = fs::last_write_time(m_path, ec);
    if (ec || t == m_fileTime) return false;
    auto text = readFile(m_path);
    if (!text) return false;
    m_fileTime = t;
    if (*text == m_text) return false;
    m_text = std::move(*text);
    lookUpTrust();  // another program wrote it: the new text is asked about
    post();
    return true;
}

void ViewerState::autosave(bool force) {
    // The last write's text is on disk once it is done (waited for when forced).
    if (m_autosaving.valid() && (force || m_autosaving.wait_for(std::chrono::seconds(0)) == std::future_status::ready))
        if (m_autosaving.get()) m_autosaved = std::move(m_autosavingText);
    auto now = std::chrono::steady_clock::now();
    if (!force && (now - m_lastAutosave < std::chrono::seconds(2) || m_autosaving.valid())) return;
    m_lastAutosave = now;
    if (m_text == m_autosaved) return;
    const fs::path path = m_autosaveDir / "autosave.lsys";
    auto writeHere = [&] {
        std::string error;
        if (saveTextAtomically(path, m_text, error)) m_autosaved = m_text;
    };
    if (force) return writeHere();
    m_autosavingText = m_text;
    try {
        m_autosaving = std::async(std::launch::async, [path, text = m_autosavingText] {
            std::string error;
            return saveTextAtomically(path, text, error);
        });
    } catch (const std::system_error&) {  // no thread to be had: written here
        writeHere();
    }
}

std::optional<std::string> ViewerState::recoverable() const {
    if (!m_crashedBefore || m_recovered.empty() || m_recovered == m_text) return std::nullopt;
    return m_recovered;
}

void ViewerState::discardRecovery() { m_crashedBefore = false; }

void ViewerState::markCleanExit() {
    std::error_code ec;
    fs::remove(m_autosaveDir / "session", ec);
}

}  // namespace sprout::viewer
