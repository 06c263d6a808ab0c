#pragma once
// The viewer window's state that lives next to the GL context: renderer, camera, view
// settings, the cached 3D image, status messages. Split by feature: window.cpp (start-up,
// loop), window_view.cpp (the 3D view: uploads, moving and still frames), window_present.cpp
// (the panel's cache, the copy to the screen), window_input.cpp (mouse, keys),
// app_actions.cpp (files, screenshots, exports), panel*.cpp (the ImGui panel), script.cpp
// (scripted actions).
#include <cstdint>
#include <deque>
#include <future>
#include <iosfwd>
#include <memory>
#include <optional>
#include <utility>
#include <vector>
#include <string>

#include "app/render/renderer.hpp"
#include "app/viewer/window/editor.hpp"
#include "app/viewer/window/export_job.hpp"
#include "app/viewer/window/thumbnails.hpp"
#include "app/viewer/state/viewer_state.hpp"

struct GLFWwindow;

namespace sprout::viewer {

struct ViewSettings {
    render::RenderOptions render;
    // The sun's sliders; they start where render.sunDirection's default is (App's
    // constructor), so that the window lights a plant as `sprout render` does.
    float sunAzimuth = 0;    // degrees around +Y
    float sunElevation = 0;  // degrees above the horizon
    bool turntable = false;
    float turntableSpeed = 20;  // degrees per second
    // Every moving frame the still picture, however long it takes; otherwise only where the
    // still picture takes a few ms (a GPU, a small plant), and a lighter one elsewhere.
    bool fullWhileMoving = false;
    int screenshotSize = 0;     // index into kScreenshotSizes
    // The environment an open L-system grows in, drawn with it; a slice of its light grid.
    bool showEnvironment = true;
    bool lightSlice = false;
    float sliceHeight = 0.5f;  // 0 the plant's lowest point, 1 its top
};

struct ScreenshotSize {
    const char* label;
    int width, height;  // 0: the window's view
};
inline constexpr ScreenshotSize kScreenshotSizes[] = {
    {"view size", 0, 0}, {"1920 x 1080", 1920, 1080}, {"3840 x 2160", 3840, 2160}, {"1080 x 1080", 1080, 1080}};

// The moving view's smallest share of the window's pixels each way.
constexpr float kSmallestMovingScale = 0.25f;

struct App {
    explicit App(std::string executable);

    ViewerState state;
    render::Renderer renderer;
    render::Camera camera;
    ViewSettings view;
    Thumbnails thumbnails;
    GLFWwindow* window = nullptr;

    int panelWidth = 430;
    bool needsRedraw = true;
    bool frameOnNextPlant = true;
    bool showHelp = false;
    bool interacting = false;  // dragging: no shadows for big plants
    bool scriptDragging = false;  // the script's `drag` holds the view as a mouse drag would
    // A panel's control held with the mouse (a curve's point, a slider) or the script's
    // `curve-drag`, and after it is let go until the worker has made its last plant: the
    // plants it makes are drawn at the moving view's quality, one a frame, and the still
    // picture follows with the last one (window_view.cpp). (Refined at once, the plant of the
    // step before the last was drawn still and thrown away, while the worker derived the last
    // on the same cores.)
    bool shaping = false;
    bool shapingHeld = false;  // the control held (or the script's drag) at the last frame
    bool scriptShaping = false;
    // The script's mouse (`mouse-drag-point`): while `on`, ImGui gets this position and left
    // button each frame in place of the window system's (window.cpp, after the backend's frame).
    struct { bool on = false, down = false; float x = 0, y = 0; } scriptMouse;
    bool bigPlant = false;     // uploaded at interactive detail
    unsigned imageTexture = 0; // an iterated function system's density image
    // The 3D view as last drawn: copied to the window each frame, drawn again only when
    // something changed (needsRedraw, its size, its quality), so a still scene costs a copy.
    unsigned viewFbo = 0, viewColour = 0;
    int viewWidth = 0, viewHeight = 0;
    // While the view moves it is drawn at half the size and stretched (a software rasteriser
    // pays per pixel); letting go draws it at full size again.
    int drawWidth = 0, drawHeight = 0;  // the size the cached view was drawn at
    bool viewInteractive = false;
    std::uint64_t viewDraws = 0;  // how many times the 3D view was drawn
    std::uint64_t sketchDraws = 0;  // of those, moving frames of a big scene drawn as its sketch
    std::uint64_t fullMovingDraws = 0;  // and moving frames drawn at full quality (a fast scene)
    std::uint64_t stagedUploads = 0;    // plants that went to the GPU a piece per frame
    // The still view is drawn a piece per frame (Renderer::beginDraw), so that no frame of the
    // panel waits for a whole big plant on a software rasteriser: the pieces are sized to take
    // about kRefineMs each, and the view shows its last picture until the new one is whole.
    bool refining = false;
    std::uint64_t presentedUi = 0;  // the panel last shown (a hash of ImGui's draw data)
    // Frames whose panel was copied from the one drawn before (unchanged), and drawn anew.
    std::uint64_t panelCopies = 0, panelDraws = 0;
    int presentedWidth = 0, presentedHeight = 0;
    float movingScale = 0.5f;  // the moving view's share of the pixels each way (kSmallestMovingScale to 0.5)
    bool sceneArrived = false;  // a new scene is on the GPU: shown first as a preview when big
    bool movingWarm = false;    // the moving view has been drawn once in this window
    double lastStillMs = 0;     // what the last still view took to draw (its pieces together)
    glm::mat4 drawnCamera{0.0f};  // the camera (projection and view) the view was last drawn from
    double refineStart = 0;             // when the picture in pieces was begun (glfwGetTime)
    double refineWorstMs = 0;           // the longest frame while the last picture was refined
    int refineFrames = 0;               // and the frames it took
    // The last moving picture as shown (stretched to the view's size), kept when a script
    // measures how close it is to the still view that follows (frame-stats' moving_differ_pct:
    // the share of pixels that differ by more than 30 of 765).
    bool measureMoving = false;
    bool viewMoving = false;  // the view's picture is a moving one
    bool viewPending = false;  // drawn in this frame, shown in the next (drawView)
    std::vector<std::uint8_t> movingPicture;
    double movingDifferPct = -1;
    std::string movingWorstWhat;  // what the longest moving frame did (frame-stats)
    // Frames that drew the moving view (script frame-stats): the longest, their sum and count.
    double movingWorstMs = 0, movingTotalMs = 0;
    std::uint64_t movingFrames = 0;
    std::string status;        // last action's message
    double statusTime = 0;
    double uploadMs = 0, drawMs = 0, frameMs = 0, worstFrameMs = 0;

    // Pending file dialogs (a path typed in a popup).
    bool openPopup = false, saveAsPopup = false, quitPopup = false, exportPopup = false;
    ExportJob exportJob;
    VideoJob videoJob;
    bool videoPopup = false;
    int videoKind = 0;  // 0 growth, 1 turntable
    std::string pathInput;
    bool quitRequested = false;
    bool quitConfirmed = false;
    int jumpTo = -1;  // byte offset the editor's cursor goes to (a clicked error)
    editor::Editor editor;        // the grammar editor (app/viewer/editor)
    std::string editorDocument;   // the document it holds: a new one starts a new undo history

    void say(std::string message);
    // Opens a file (edits in progress go to the autosave first) and frames it.
    void openFile(const std::string& path);
    // Saves to the current file, or asks for a name.
    void save();
    void frame();  // camera on the current plant
    void resetView();
    void applySun();
    // The environment of the plant on screen, drawn as the view settings say (a new plant, a
    // toggle; `environmentDirty` asks for it), on a thread: a light slice of a big plant takes
    // a few hundred ms. updateEnvironment starts a drawing when none is being made (the
    // newest settings win: a later frame starts the next); showEnvironment puts a finished one
    // on screen once its plant is whole there (a drawing of a plant gone since is dropped).
    void updateEnvironment();
    void showEnvironment();
    // The view shows the plant on screen whole: uploaded, its environment drawn, its still
    // picture finished (scripts and --screenshot wait for this).
    bool viewSettled() const {
        return !refining && !viewPending && !renderer.uploading() && !environmentJob.valid() && !environmentDirty && environmentOf == state.plant();
    }
    bool environmentDirty = true;
    std::shared_ptr<const Result> environmentOf;  // the plant whose environment is drawn or being drawn
    struct EnvironmentDrawing {
        Mesh mesh;
        std::string error;
        std::shared_ptr<const Result> plant;
    };
    std::future<EnvironmentDrawing> environmentJob;
    bool takeScreenshot(const std::string& path, int width, int height);
    // Writes the plant on screen as .glb, .obj, .ply or .svg on a background thread.
    void exportModel(const std::string& path);
    // Records the plant on screen as a growth or turntable video (a child process renders it).
    void recordVideo(const std::string& kind, const std::string& path);
    std::string nextScreenshotPath() const;

    // Picking (app/viewer/window/picking.cpp): what a click in the 3D view hit, the module that drew
    // it and the rule that made it, its ancestors; and everything one rule made.
    struct Selection {
        std::shared_ptr<const Result> plant;  // the plant it was picked on
        bool surface = false;                 // a leaf, petal or sphere; else a stem segment
        std::uint32_t instance = 0;           // index of the segment or surface
        std::uint32_t module = 0;             // its module in the drawn string
        std::vector<LineageLink> links;       // empty when the derivation cannot say (a homomorphism)
        int forestPlant = -1;                 // a forest: which plant (its species in plant->forest)
        std::string text;                     // the module as written, "F(1.5)" (made once, when picked)
    };
    std::optional<Selection> selection;
    std::optional<std::pair<double, double>> pendingPick;  // a click waiting for the derivation's origins
    int highlightLine = 0;           // a rule's line: every segment it made is highlighted
    std::size_t highlightCount = 0;  // how many (stems and surfaces)
    bool highlightDirty = false;
    std::shared_ptr<const Result> highlightOf;  // the plant the highlight was made for
    bool followCursor = true;        // highlight the rule under the editor's cursor
    int cursorLine = 0;              // the rule under the cursor: the line it last followed
    // Picks at window pixel (x, y); false (and asks for origins) when the plant has none yet.
    bool pickAt(double x, double y);
    // The line printed by the script's `pick`: "module=F index=12 step=3 rule_line=7".
    std::string describeSelection() const;
    void setHighlightLine(int line);
    void updateHighlight();  // the highlight mesh for the selection and the highlighted rule
    // Picks module `index` of the drawn string (the inspector): its first stem or surface.
    void selectModule(std::uint32_t index);
    // The selection of module `module` of the drawn string, drawn by segment or surface `instance`.
    Selection selectionOf(std::shared_ptr<const Result> plant, std::uint32_t module, bool surface, std::uint32_t instance) const;

    // The derivation inspector's state (app/viewer/window/inspector.cpp).
    struct Inspector {
        int step = -1;
        std::uint64_t first = 0;    // the first module listed
        std::int64_t chosen = -1;
        char query[64] = "";
        bool found = true;
        std::shared_ptr<const Result> of;  // what the caches below are for
        int cachedStep = -1;
        std::vector<std::uint64_t> checkpoints;
        std::vector<std::int32_t> made;
        // The chosen module's rule and matched context, as shown (made once per choice).
        std::int64_t describedChoice = -1;
        std::vector<std::string> description;
    } inspector;
    // Words the editor completes, made once per plant.
    std::vector<std::string> completions;
    std::shared_ptr<const Result> completionsOf;
    bool openInspector = false;  // the script's `inspect` opens its panel section
};

void drawPanel(App& app);
void inspectorSection(App& app);
// What the inspector says of module `module` of step `step`: the module, the rule that made
// it, and the context that matched (one line each).
std::vector<std::string> describeModule(const DerivationRecord& record, int step, std::uint32_t module);

// --script FILE: one action per line, run as the window goes (tests, demos).
class Script {
public:
    bool load(const std::string& path, std::string& error);
    // Runs the actions that can run now; false once `quit` ran or the script ended.
    bool step(App& app);
    bool empty() const { return m_lines.empty() && m_dragFrames == 0 && m_curve.frames == 0 && m_mouse.frames < 0; }
    // Its next action waits for the worker's result, and nothing moves meanwhile: the window
    // need not draw frames until the worker is done (as when the user waits for a plant).
    bool waitsForWorker(const App& app) const;

private:
    std::deque<std::string> m_lines;
    std::uint64_t m_waitFor = 0;  // the generation the last action posted
    bool resultIn(const App& app) const;  // the worker's result for m_waitFor has come
    double m_sleepUntil = 0;
    int m_dragFrames = 0;           // `drag`: frames still to move
    bool m_thumbnailsSeen = false;  // `wait-thumbnails`: a frame has polled them since
    float m_dragYaw = 0, m_dragPitch = 0;  // degrees a frame
    // `curve-drag`: a curve's point moved a step a frame, as the mouse moves it (one gesture),
    // nothing waited for; its longest frame, and when it ended (`curve-drag-stats`).
    struct CurveDrag {
        std::string name;
        std::size_t point = 0;
        double dx = 0, dy = 0;
        int frames = 0;
        std::uint64_t gesture = 0;
        double lastFrame = 0, worstMs = 0, startedAt = 0, endedAt = 0;
        double resultAt = 0;  // when the drag's last result came from the worker
        int shown = 0;        // plants drawn while the point moved (the picture follows the drag)
        std::uint64_t lastGeneration = 0;
    } m_curve;
    // `mouse-drag-point`: the open curve's point pressed, dragged and let go with the mouse as
    // ImGui sees it. `frames` counts the drag's frames from -1 (none) through its steps.
    struct MouseDrag {
        std::size_t point = 0, u = 0, v = 0;
        bool surface = false;  // `mouse-drag-surface-point`: point (u, v) of the surface editor's
        float dx = 0, dy = 0, x = 0, y = 0;
        int steps = 0, frames = -1;
    } m_mouse;
    bool mouseStep(App& app);
    // A line's command run (script.cpp, by kind); nullopt: not one of that kind.
    std::optional<bool> documentCommand(App& app, const std::string& cmd, std::istringstream& in);
    std::optional<bool> curveCommand(App& app, const std::string& cmd, std::istringstream& in);   // script_curves.cpp
    std::optional<bool> objectCommand(App& app, const std::string& cmd, std::istringstream& in);  // script_curves.cpp
    std::optional<bool> reportCommand(App& app, const std::string& cmd, std::istringstream& in);
    std::optional<bool> pickCommand(App& app, const std::string& cmd, std::istringstream& in);
    bool viewCommand(App& app, const std::string& cmd, std::istringstream& in);
};

}  // namespace sprout::viewer
