#pragma once
// Everything the viewer knows, without a window: the grammar text (the single source of
// truth), the requests it posts to the worker, the last good plant, the iteration being
// shown and its animation, the file it came from and its autosave. The ImGui panel edits
// this; tests drive it directly.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/plant/vlab_view.hpp"
#include "app/viewer/state/trust.hpp"
#include "app/viewer/state/worker.hpp"

namespace sprout::viewer {

// Writes `text` to `path` atomically (temporary file, fsync, rename): a failed save keeps
// the old file. False with the reason in `error`.
bool saveTextAtomically(const std::filesystem::path& path, const std::string& text, std::string& error);

class ViewerState {
public:
    // `autosaveDir` empty: $XDG_STATE_HOME/sprout. `trustFile` empty: beside the autosave when
    // `autosaveDir` is given (tests keep to their folder), else TrustStore's default.
    explicit ViewerState(std::filesystem::path autosaveDir = {}, std::filesystem::path trustFile = {});
    ~ViewerState();

    // --- the grammar text
    const std::string& text() const { return m_text; }
    void setText(std::string text, std::uint64_t gesture = 0);  // an edit: re-derive
    // The gesture of the last edit (a drag in the panel: one id for all its changes, which the
    // grammar editor's undo takes back as one step); 0 for any other edit.
    std::uint64_t textGesture() const { return m_textGesture; }
    bool dirty() const { return m_dirty; }

    // --- sliders write into the text
    void setDirectiveValue(const std::string& key, double value);
    void setDefineValue(const std::string& name, double value);
    void setIterations(int n);
    void setSeed(std::uint64_t seed);
    void newSpecimen();  // another seed: another plant of the same species

    // --- iteration stepping and growth animation
    int displayStep() const { return m_displayStep; }
    void setDisplayStep(int step);  // clamped to 0..n
    void stepBy(int delta);
    bool playing() const { return m_playing; }
    void setPlaying(bool on);
    // Picking: the derivation keeps where each module came from (8 bytes a module), asked for
    // on the first click and kept while the viewer is open.
    bool picking() const { return m_picking; }
    void setPicking(bool on);
    float stepsPerSecond = 2.0f;
    bool loop = true;
    bool smoothGrowth = true;  // new segments grow from nothing while their step plays
    void tick(double seconds);  // advances the animation

    // --- trust before code runs (app/viewer/state/trust.hpp): an L-Py text from outside runs its
    // Python only once the user said so; presets and typed text need no answer.
    // True when the text is an L-Py model whose Python is not run (the panel's bar).
    bool pythonBlocked() const;
    // True when no answer is kept for it yet: the panel asks.
    bool pythonQuestion() const { return pythonBlocked() && m_trust == TrustAnswer::None; }
    std::vector<PythonImport> imports() const { return pythonImports(m_text); }
    // The user's answer, kept by the text's hash; Trusted runs the model.
    void answerTrust(bool trusted);
    const TrustStore& trustStore() const { return m_trustStore; }
    // A recovered text is text from outside: restored with its trust looked up.
    void restoreRecovered();

    // --- results: call once per frame; true when a new plant arrived
    bool update();
    std::shared_ptr<const Result> plant() const { return m_plant; }        // last good one
    std::shared_ptr<const Result> latest() const { return m_latest; }      // errors of the text
    const Worker& worker() const { return m_worker; }
    Worker& worker() { return m_worker; }
    std::uint64_t generation() const { return m_generation; }
    // Blocks until the newest request is done (tests and screenshots only).
    void waitForPlant();

    // --- files
    const std::filesystem::path& path() const { return m_path; }
    FileKind kind() const { return m_kind; }  // of the text: Lsys, Cpfg, Ifs or Forest
    // Opens a .lsys file, or imports an Lparser .ls / Fractint .l one (`system` picks one
    // of a Fractint file's systems); an import has no path until it is saved as .lsys.
    bool open(const std::filesystem::path& path, std::string& error, const std::string& system = {});
    // The file as it is (open() without looking for a VLab object around it).
    bool openFile(const std::filesystem::path& path, std::string& error, const std::string& system = {});
    // The file an import came from, and a Fractint file's systems to choose from.
    const std::filesystem::path& importedFrom() const { return m_importedFrom; }
    const std::vector<std::string>& importSystems() const { return m_importSystems; }
    // The VLab object open (a folder, or a file in it, with a `specifications`): open() opens
    // the L-system its cpfg line runs, whose view and colours the worker applies.
    const std::optional<VlabSummary>& vlabObject() const { return m_vlab; }
    // A preset (named `preset`) or a restore; a path when the text is that file's.
    void openText(std::string text, std::filesystem::path path = {}, std::string preset = {});
    // The panel's title: the file name, the preset's name, or "untitled".
    std::string title() const;
    bool save(std::string& error);
    bool saveAs(const std::filesystem::path& path, std::string& error);
    // Reloads the file when another program changed it (and the text here has no unsaved
    // edits); true when it did.
    bool reloadIfChangedOnDisk();
    // A file beside the text that its parse reads changed (an object's function or contour,
    // written by the panel's editor): derive again, reading it anew.
    void filesChanged();
    // Autosave of the working text, every few seconds while it has unsaved edits. Written on
    // a thread of its own (its fsyncs took 2-3 ms here, far more on a busy or network disk,
    // in the middle of a drag); `force` writes it before returning (leaving, saving).
    void autosave(bool force = false);
    // Text left by a session that did not end cleanly, if any.
    std::optional<std::string> recoverable() const;
    void discardRecovery();
    void markCleanExit();

private:
    void post(std::uint64_t gesture = 0);  // gesture: the drag the edit is a step of
    void lookUpTrust();  // the text came from outside


    Worker m_worker;
    std::string m_text;
    bool m_dirty = false;
    std::uint64_t m_textGesture = 0;
    std::uint64_t m_generation = 0;
    std::uint64_t m_filesVersion = 0;
    std::optional<std::uint64_t> m_seedOverride;
    int m_displayStep = -1;  // -1: follow n
    bool m_playing = false;
    bool m_picking = false;
    double m_animClock = 0;
    float m_growFraction = 1.0f;
    std::shared_ptr<const Result> m_plant, m_latest;
    std::filesystem::path m_path;
    FileKind m_kind = FileKind::Lsys;
    std::string m_preset;  // the preset opened, until saved under a name
    std::filesystem::path m_importedFrom;
    std::optional<VlabSummary> m_vlab;
    std::vector<std::string> m_importSystems;
    std::filesystem::file_time_type m_fileTime{};
    std::filesystem::path m_autosaveDir;
    std::chrono::steady_clock::time_point m_lastAutosave{};
    std::string m_autosaved;
    std::future<bool> m_autosaving;  // a write on its thread, of m_autosaving text
    std::string m_autosavingText;
    std::string m_recovered;  // the text autosaved by a session that did not end cleanly
    bool m_crashedBefore = false;
    TrustStore m_trustStore;
    TrustAnswer m_trust = TrustAnswer::Trusted;
};

}  // namespace sprout::viewer
