#pragma once
// A parsed grammar: the alphabet, the axiom, productions indexed by predecessor symbol and
// the directives' values. Produced by parse(), read by derive() and the turtle.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/base/shine.hpp"
#include "core/language/alphabet.hpp"
#include "core/language/diagnostic.hpp"
#include "core/language/environment_spec.hpp"
#include "core/language/expr.hpp"
#include "core/language/module_string.hpp"
#include "core/language/surface_file.hpp"
#include "core/language/vlab/curve_files.hpp"

namespace sprout {

namespace vlab {
struct BackgroundScene;  // core/language/vlab/background_scene.hpp
}

// A value with optional seeded jitter: `angle: 22 ~ 4` is mean 22, sigma 4.
struct Jittered {
    double mean = 0;
    double sigma = 0;
};

enum class Toggle { Auto, On, Off };
enum class ViewHint { Auto, Flat, Solid };  // `view: 2d` / `view: 3d`

// The picture a VLab object's view file, animation file and cpfg line ask for (app/plant/
// vlab_view.cpp): cpfg's camera, light, background, window and animated steps. Unset for
// other grammars, whose pictures are framed by the renderer's own choice.
struct PictureView {
    std::array<double, 3> eye{0, 0, 1}, target{0, 0, 0};  // viewpoint, view reference point
    double twist = 0;         // degrees about the viewing direction
    bool perspective = false; // false: parallel projection
    double viewingAngle = 45; // degrees, perspective
    double scale = 1;         // scale factor: > 1 closer
    std::array<double, 3> light{1, 0, 0};  // towards the light
    std::optional<std::uint32_t> background;  // 0xRRGGBB
    std::optional<std::uint32_t> ink;  // 0xRRGGBB: a planar curve's colour (its initial colour)
    int width = 0, height = 0;  // -w: the window's size (0: unset)
    std::vector<int> frames;    // the derivation steps an animation shows (empty: all)
    // `background scene:`: drawn after the plant (app/plant/growth.cpp), null when none.
    std::shared_ptr<const vlab::BackgroundScene> backgroundScene;
};

struct Settings {
    int iterations = 0;
    Jittered angle{90, 0};  // degrees
    Jittered step{1, 0};
    double width = 0;         // stem diameter in step units; 0: automatic, from the plant's size
    double widthFactor = 0.7; // `!` multiplies the width by it, `#` divides
    double branchLength = 1;  // branch_scale: factors applied at each `[`
    double branchWidth = 1;
    double stepScale = 1;     // step_scale: length factor per derivation step
    // cpfg's turtle scale (the view file's initial scale: and scale multiplier:): F's length,
    // widths set by number and sizes are multiplied by the scale, which @D, @Di, @Dd change.
    double initialScale = 1, scaleMultiplier = 1;
    std::array<double, 3> tropism{0, 0, 0};  // tropism: x y z e (ABOP 2.2)
    double tropismStrength = 0;
    // cpfg's tropisms and torques (the view file's `tropism:` and `torque:` lines; movements.c):
    // before each F, f, G and g the heading bends towards the sum of the tropisms' directions,
    // each weighted by its elasticity (one at an angle bends towards that angle to it), and
    // the up vector turns by the torques; @Ts, @Ti, @Td change a turtle's elasticities.
    struct Movement {
        bool torque = false;
        std::array<double, 3> direction{0, 0, 0};  // times the intensity
        double angle = 0, elasticity = 0, step = 0;
    };
    std::vector<Movement> movements;
    std::vector<std::uint32_t> palette;  // 0xRRGGBBAA; empty: the default palette
    // `material: INDEX #rrggbb [transparency T] ...`: the palette's entry INDEX (over the
    // default palette when none is given), its alpha 1 - T. The turtle applies them in order.
    struct MaterialEntry {
        int index = 0;
        std::uint32_t rgba = 0xFFFFFFFF;
    };
    std::vector<MaterialEntry> materials;
    // The palette entries that shine (specular, shininess, emission), by index.
    std::vector<std::pair<int, Shine>> shines;
    // The palette entries drawn with an image (`material: ... texture FILE`, L-Py's Texture2D and
    // ImageTexture materials), by index: the image's path, relative to the model's folder or
    // absolute. Surfaces with texture coordinates (patches, cpfg surfaces, generalized cylinders)
    // show it, times the entry's colour; the others keep the colour.
    std::vector<std::pair<int, std::string>> textures;
    // A VLab object's textures (its view file's `texture: F: FILE ...` lines, cpfg's): `@Tx(n)`
    // draws the surfaces after it with the n-th, `@Tx` with none. `perSurface` (cpfg's `S:`):
    // the image spans the whole surface (by its x and y), else each of its patches.
    struct ViewTexture {
        std::string file;  // as the view file's folder resolves it
        bool perSurface = false;
        // On a generalized cylinder cpfg keeps the image's proportions (update_segment_texture):
        // v grows by length / (pi x width) x aspect / ratio, `aspect` the image's width over its
        // height, `ratio` the line's `R:`.
        float aspect = 1, ratio = 1;
    };
    std::vector<ViewTexture> viewTextures;
    // cpfg's colour index and width steps (a VLab object's view file): the index the turtle
    // starts with (-1: none, colours by branch order), what `;` and `,` add, and, when set,
    // what `!` and `#` subtract and add (instead of widthFactor's product).
    int initialColour = -1;
    int colourIncrement = 1;
    std::optional<double> widthIncrement;
    std::optional<PictureView> picture;  // a VLab object's picture
    // Cross-sections for generalized cylinders, by SetContour(k): x y pairs, the stem's radius
    // one unit (x along the turtle's left, y along its up); closed when the last point is the
    // first. Made by the L-Py drawing (PlantGL's SetContour and Sweep curves).
    std::vector<std::vector<float>> sections;
    // The texts of Label(k[, size]) (made by the L-Py drawing: its @L and Label).
    std::vector<std::string> labels;
    Toggle gradient = Toggle::Auto;      // colour by branch order (Auto: when no colour modules)
    // Inside { }, F draws its segment as well as a polygon point (PlantGL's turtle, for L-Py
    // files); false: F only outlines the polygon (cpfg).
    bool polygonEdgesDrawn = false;
    // L-system Explorer: `{(0)` (a '{' with a parameter) starts a path, a tube through the
    // points F reaches (as @Gs does), and a '}' with no polygon open ends it.
    bool bracePaths = false;
    std::uint32_t barkColour = 0x6B4A2EFF, tipColour = 0x7DB344FF;
    ViewHint view = ViewHint::Auto;
    std::uint64_t seed = 1;
    bool seedGiven = false;  // cpfg: a `seed:` line makes the L-system stochastic
};

// One module of a predecessor or context: a name, and either named formal parameters or
// (in contexts, when written without parentheses) any parameter count.
struct PatternModule {
    SymbolId symbol = 0;  // exact symbol when arity is fixed
    NameId name = 0;
    int arity = 0;        // -1: matches the name with any parameters
    bool wildcard = false;  // `*`: any module
    std::uint16_t firstSlot = 0;  // where this module's parameters are bound
};

// A file a cpfg model opens (`fp = fopen("data.txt", "r");`, core/language/cpfg/user_files.cpp):
// one opened for reading is read whole, from the model's folder, when the grammar is read, and
// fscanf reads on from the offset kept in the hidden global slot `cursor`; what a model writes
// (fprintf) is not written.
struct UserFile {
    std::string name, mode;
    bool readable = false;      // opened for reading, and read
    std::string text;
    std::uint16_t cursor = 0;   // the global slot of the offset fscanf reads from next
};

// A cpfg statement in a production's block: `x = expr;` or `if (c) ... else ...`. Locals
// are slots after the formal parameters, so the condition and successor read them.
struct Statement {
    // Eval: an expression run for what it does (cpfg's `srand(3);`); While, Do: `then` is the
    // loop's body (run at most kMaxLoop times). Open: `slot = fopen(...)`, the file `file`;
    // Scan: `fscanf(expr, format, &targets...)`, its count into `slot` when `size` is 1.
    enum class Kind : std::uint8_t { Assign, If, Eval, While, Do, Open, Scan } kind = Kind::Assign;
    static constexpr int kMaxLoop = 1'000'000;
    std::uint16_t slot = 0;      // Assign: where the value goes
    std::uint16_t size = 0;      // Assign to an array's element: the array's size (0: a variable)
    Expr index;                  // ... and its flat index, from `slot`
    Expr expr;                   // Assign: the value; If, While, Do: the test; Scan: the file
    std::vector<Statement> then, otherwise;
    std::uint16_t file = 0;                         // Open: the index of its file in `files`
    std::vector<std::uint16_t> targets;             // Scan: the slots its numbers go to
    std::vector<std::string> pieces;                // Scan: the format, one conversion a piece (%lf, %d)
    std::shared_ptr<const std::vector<UserFile>> files;  // Open, Scan: the grammar's files
};

struct Successor {
    std::vector<SymbolId> symbols;
    std::vector<Expr> args;  // one per parameter, in string order
    size_t paramCount() const { return args.size(); }
};

struct Production {
    int line = 0;
    std::string label;  // ABOP's "p1:" before the rule, as written (empty: none)
    std::vector<PatternModule> left;   // in text order; matched right to left
    PatternModule pred;
    std::vector<PatternModule> predRest;  // cpfg: the strict predecessor's next modules (`AB --> C`), matched in a row
    std::vector<PatternModule> right;  // in text order
    std::optional<Expr> condition;
    std::vector<Statement> pre, post;  // cpfg blocks: before the condition, after it holds
    std::uint16_t firstLocal = 0;      // slots from here to slotCount are the blocks' locals
    Successor successor;
    double probability = -1;  // < 0: deterministic
    // cpfg's probability written as an expression of the production's parameters (`: x`),
    // evaluated when the production applies; `probability` is then 1 (not deterministic).
    std::optional<Expr> probabilityExpr;
    int slotCount = 0;        // formal parameters across left, pred and right
    std::uint8_t lsystem = 0; // cpfg's sub-L-system it belongs to: 0 the main one, k subLsystems[k-1]
    bool hasContext() const { return !left.empty() || !right.empty() || !predRest.empty(); }
    bool stochastic() const { return probability >= 0; }
    bool hasBlocks() const { return !pre.empty() || !post.empty(); }
};

struct RuleSet {
    std::vector<Production> productions;         // in file order
    std::vector<std::vector<std::uint32_t>> bySymbol;  // symbol -> indices into productions
    void index(size_t alphabetSize);
};

struct Grammar {
    Alphabet alphabet;
    ModuleString axiom;
    RuleSet rules;           // derivation productions
    RuleSet interpretation;  // cpfg homomorphism: applied when drawing, never stored
    RuleSet decomposition;   // cpfg decomposition: applied after each step until none applies
    int interpretationDepth = 1;  // `maximum depth:` of the homomorphism (recursion levels)
    int decompositionDepth = 32;  // `maximum depth:` of the decomposition
    // cpfg's cut: a '%' stays in the string of the step that made it and removes the rest of
    // its branch while the next step is derived. In .lsys it cuts at once (ABOP 1.10.3).
    bool cutInNextStep = false;
    // cpfg's `ring lsystem`: the string's last module is the left context of its first, and
    // the first the right context of the last.
    bool ring = false;
    // Whether the decomposition rules rewrite the axiom before the first step (lpfg and L-Py);
    // cpfg applies them within each step only (generate.c, ApplyProd), so its step 0 is the
    // axiom as written.
    bool decomposeAxiom = true;
    // cpfg's numbers: parameters kept in the string as floats (rounded as each is written);
    // its random numbers (Rng::cpfg): one stream through the derivation, and with a `seed:`
    // one draw for each module of each step, choosing among its applicable productions (each
    // of probability 1 unless given), as cpfg's generate.c does.
    bool cpfgRandom = false;
    // cpfg's sub-L-systems (`lsystem: 2` after the main one's `endlsystem`), by label: between
    // `$(2)` and `$` a step rewrites with sub-L-system 2's productions (L-system Explorer).
    std::vector<double> subLsystems;
    Settings settings;
    // cpfg's global variables, by the slot kGlobalSlot + i (expr.hpp), and the blocks that run
    // before the derivation (Start:), before and after each step (StartEach:, EndEach:) and
    // after it (End:), with a production's blocks, in order, left to right.
    std::vector<std::string> globals;    // an array's elements after its name: "" (never a name)
    std::vector<double> globalInit;      // their values before the Start: block (arrays' initialisers)
    std::vector<GlobalArray> arrays;
    std::vector<Statement> startBlock, startEachBlock, endEachBlock, endBlock;
    std::shared_ptr<std::vector<UserFile>> userFiles;  // what fopen opens (null: none)
    bool hasGlobals() const { return !globals.empty() || !startBlock.empty() || !startEachBlock.empty() || !endEachBlock.empty(); }
    std::vector<bool> ignored;  // by NameId: skipped when matching contexts
    std::unordered_map<std::string, double> defines;
    Environment environment;  // what ?E modules ask after each step (`environment:` lines)
    // cpfg surface files by module name ("~s"): `surface: s leaf.s` or an `s.s` beside the grammar.
    std::unordered_map<std::string, std::shared_ptr<const SurfaceFile>> surfaceFiles;
    // cpfg's functions (func(id, x)) and contours (@#(id)) from the view file: ParseOptions::curves.
    std::shared_ptr<const CurveTables> curves;
    std::vector<std::string> defineOrder;  // for sliders, in file order
    // How the text was read, for a user who pasted it: the dialect (".lsys", "ABOP notation",
    // "cpfg"; the loader names Lparser, Fractint and L-Py) and each setting taken from it.
    struct ReadSetting {
        int line = 0;
        std::string name;     // the setting it became: "angle", "n", "axiom", "define"
        std::string value;    // as written after the key
        std::string written;  // the key as written ("δ", "delta", "w"), when not the name
    };
    std::string dialect = ".lsys";
    std::vector<ReadSetting> settingsRead;

    bool parametric() const;        // any module with parameters in axiom or successors
    bool hasContext() const;
    bool stochastic() const;
    bool usesCut() const;
    bool hasQueries() const;        // ?P ?H ?U ?L ?E modules: the string is interpreted after each step
    // Anything the D0L fast path cannot do: decomposition, queries, statement blocks.
    bool needsGeneralEngine() const;
};

// The setting a key names in any notation Sprout reads ("δ", "delta", "w", "ω", "start",
// "dlength", "derivation length" ...): the directive's name ("angle", "axiom", "n"), or nullptr.
const char* settingNamed(std::string_view key);
// How a text was read, a line each: each setting taken from it ("line 2: angle = 25.7
// (written 'δ')"), each constant, each labelled rule; for `sprout expand --stats` and the panel.
std::vector<std::string> settingsReadLines(const Grammar& g);

struct ParseResult {
    std::shared_ptr<const Grammar> grammar;  // null when there are errors
    std::vector<Diagnostic> diagnostics;     // errors and warnings, in line order
    bool ok() const { return grammar != nullptr; }
};

// What a module asks after each step: 'P' 'H' 'U' 'L' for the turtle's position and frame
// (cpfg query modules), 'E' for the environment (communication module), 0 for anything else.
inline char queryKind(std::string_view name) {
    if (name.size() != 2 || name[0] != '?') return 0;
    return std::string_view("PHULE").find(name[1]) != std::string_view::npos ? name[1] : 0;
}

// Reads the file named by an `#include` (cpfg family): its text, or nullopt with `error` set.
using IncludeReader = std::function<std::optional<std::string>(const std::string& name, std::string& error)>;

struct ParseOptions {
    bool cpfg = false;       // the cpfg / lpfg / L-Py family instead of .lsys
    IncludeReader include;   // null: `#include` is an error (text typed with no folder)
    std::string fileName;    // the grammar's own name, so that it cannot include itself
    std::string folder;      // its folder ("": text typed with no file): texture images beside it
    bool explorer = false;   // an L-system Explorer file (`.ls`, not Lparser's): that tool's defaults
    // cpfg's own lexer (lsys_input.l): a newline followed by a tab does not end a line, so a
    // line that starts with a tab goes on the one before (a successor over several lines).
    // Set for cpfg's `.l` files, not L-Py's (Python indents with tabs) nor Explorer's.
    bool tabContinues = false;
    // A VLab object's `-e FILE.e` environment program (readEnviroFile): the grammar's
    // environment.program, which answers its ?E modules.
    std::shared_ptr<const EnvironmentProgram> environmentProgram = nullptr;
    // A VLab object's view file's `surface: p petal.s 2` lines: the surface file of `~p`,
    // read beside the grammar (an `.s` named as the module, or a `surface:` line in the
    // grammar, comes first).
    std::vector<std::pair<std::string, std::string>> surfaces;
    // cpfg's functions and contours, read from the files a VLab object's view file names
    // (core/language/vlab/): func(id, x) and its names, @#(id). Kept by the Grammar.
    std::shared_ptr<const CurveTables> curves{};
    // A VLab object's view file's textures (Settings::viewTextures).
    std::vector<Settings::ViewTexture> viewTextures;
};

ParseResult parse(std::string_view text);
ParseResult parse(std::string_view text, const ParseOptions& options);

// Reads files for `#include` from `folder` only: a name that leads outside it (`..`, an
// absolute path, a symbolic link out) is refused with a message.
IncludeReader includeFromFolder(std::string folder);

}  // namespace sprout
