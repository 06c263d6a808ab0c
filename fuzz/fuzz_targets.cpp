// libFuzzer targets, one per input Sprout reads. Built with clang by scripts/fuzz.sh (see
// fuzz/CMakeLists.txt); each target is this file compiled with SPROUT_FUZZ_<NAME> defined.
// A crash, a sanitizer report, a leak or a timeout is a failure; every input must end in a
// value or in diagnostics.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>

#include "core/derive/derive.hpp"
#include "core/environment/cpfg_programs/enviro_file.hpp"
#include "core/language/expr.hpp"
#include "core/language/file_kind.hpp"
#include "core/language/grammar.hpp"
#include "core/language/import/import.hpp"
#include "core/language/vlab/animation_file.hpp"
#include "core/language/vlab/background_scene.hpp"
#include "core/language/vlab/colours.hpp"
#include "core/language/vlab/view_file.hpp"
#include "core/language/vlab/curve_files.hpp"
#include "core/language/vlab/surface_patches.hpp"
#include "core/base/rng.hpp"
#include "core/turtle/background_scene.hpp"
#include "core/turtle/turtle.hpp"
#include "lpy/translate/translate.hpp"
#if defined(SPROUT_FUZZ_IMAGE)
#include "app/mesh/texture_images.hpp"
#endif
#if defined(SPROUT_FUZZ_LPY)
#include "app/plant/lpy_materials.hpp"
#include "app/plant/lpy_objects.hpp"
#include "app/plant/lpy_patches.hpp"
#include "app/plant/lpy_scalars.hpp"
#endif

namespace {

using namespace sprout;

// A failed check: says which on stderr (scripts/fuzz.sh shows it with the input), then aborts.
[[noreturn]] [[maybe_unused]] void fail(const char* what) {
    std::fprintf(stderr, "fuzz check failed: %s\n", what);
    std::abort();
}

// Derives a few steps under a small size cap, as the viewer does on every keystroke, bounded
// so that the fuzzer stays fast; null when the text does not parse or derive.
[[maybe_unused]] std::unique_ptr<Derivation> deriveSome(ParseResult& r, int maxSteps, int& n) {
    if (!r.ok()) return nullptr;
    DeriveOptions o;
    o.limits.maxModules = 200'000;
    o.limits.maxBytes = 64ull << 20;
    auto d = std::make_unique<Derivation>(r.grammar, o);
    n = std::min(r.grammar->settings.iterations, maxSteps);
    if (!d->deriveTo(n).ok()) return nullptr;
    if (!checkDrawing(*d->step(n), *r.grammar, o.limits, n).ok()) return nullptr;  // as render and the viewer
    return d;
}

// Derives a few steps and draws the result, from the tree and from the string.
[[maybe_unused]] void deriveAndDraw(const std::string& text, int maxSteps) {
    ParseResult r = parse(text);
    int n = 0;
    auto derivation = deriveSome(r, maxSteps, n);
    if (!derivation) return;
    Derivation& d = *derivation;
    TurtleOptions t{n, d.seed(), nullptr};
    t.treeMinModules = 0;  // D0L strings of any size are drawn from the tree
    Geometry g;
    if (!interpret(*d.step(n), *r.grammar, t, g).fromTree) return;
    // Differential check: the string turtle must draw the same segments.
    t.fromTree = false;
    Geometry s;
    interpret(*d.step(n), *r.grammar, t, s);
    // Polygons are walked, not placed, but their outlines pass through placed blocks: a
    // closing vertex 1e-6 from the first one is dropped or kept by rounding, a triangle more
    // or less. Segments and surfaces must match exactly.
    const size_t ga = g.polygons.indices.size(), sa = s.polygons.indices.size();
    if (g.cylinders.size() != s.cylinders.size() || g.surfaces.size() != s.surfaces.size() ||
        (ga > sa ? ga - sa : sa - ga) > 6 + sa / 100 || g.planarCurve != s.planarCurve) {
        std::fprintf(stderr, "cylinders %zu/%zu, surfaces %zu/%zu, polygon indices %zu/%zu, planar %d/%d\n",
                     g.cylinders.size(), s.cylinders.size(), g.surfaces.size(), s.surfaces.size(), ga, sa,
                     int(g.planarCurve), int(s.planarCurve));
        fail("the tree and the string turtle drew different counts (tree/string)");
    }
    const glm::vec3 size = s.bounds.size();
    const float extent = std::max({size.x, size.y, size.z});
    if (!(extent < 1e6f)) return;  // rounding, not placement, decides there
    // The string turtle's frame drifts by rounding over long chains of turns (the tree's
    // far less); a misplaced subtree is off by whole segments.
    const float tol = 1e-2f * (1 + extent);
    auto far = [&](const glm::vec3& a, const glm::vec3& b) {
        return std::fabs(a.x - b.x) > tol || std::fabs(a.y - b.y) > tol || std::fabs(a.z - b.z) > tol;
    };
    for (size_t i = 0; i < s.cylinders.size(); ++i) {
        const CylinderInstance &x = g.cylinders[i], &y = s.cylinders[i];
        if (x.order != y.order || x.colour != y.colour || far(x.start, y.start) || far(x.end, y.end)) {
            std::fprintf(stderr, "cylinder %zu of %zu: tree (%g %g %g)-(%g %g %g) order %d colour %d, "
                         "string (%g %g %g)-(%g %g %g) order %d colour %d, tolerance %g\n", i, s.cylinders.size(),
                         x.start.x, x.start.y, x.start.z, x.end.x, x.end.y, x.end.z, int(x.order), int(x.colour),
                         y.start.x, y.start.y, y.start.z, y.end.x, y.end.y, y.end.z, int(y.order), int(y.colour), tol);
            fail("the tree and the string turtle placed a segment differently");
        }
    }
}

// The cpfg family: parsed as written (no folder: #include is an error), derived a few steps
// with decomposition and queries under the same caps, and drawn (generalized cylinders too).
[[maybe_unused]] void deriveAndDrawCpfg(const std::string& text, int maxSteps) {
    // Every other input as an L-system Explorer file (a `.ls`): that tool's leniencies
    // (unbalanced successors, stray lines, sub-L-systems, paths) are fuzzed too.
    ParseOptions o = parseOptionsFor(FileKind::Cpfg, "");
    o.explorer = text.size() % 2 == 1;
    // fopen's files for reading: a data file's text is the input's last line (fscanf reads it).
    const std::string data = text.substr(text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1);
    o.include = [&](const std::string& name, std::string& error) -> std::optional<std::string> {
        if (name.size() > 4 && name.compare(name.size() - 4, 4, ".dat") == 0) return data;
        error = "not in the fuzz input";
        return std::nullopt;
    };
    ParseResult r = parse(text, o);
    int n = 0;
    auto d = deriveSome(r, maxSteps, n);
    if (!d) return;
    Geometry g;
    interpret(*d->step(n), *r.grammar, {n, d->seed(), nullptr}, g);
}

// A cpfg environment (`-e`): the input is a .e file, its program's specification and an image,
// parted by lines "@@"; read, and the program asked over a few steps of ?E of every kind.
[[maybe_unused]] void runEnvironment(const std::string& input) {
    std::vector<std::string> parts;
    for (size_t at = 0;;) {
        const size_t end = input.find("\n@@\n", at);
        parts.push_back(input.substr(at, end == std::string::npos ? std::string::npos : end - at));
        if (end == std::string::npos || parts.size() == 3) break;
        at = end + 4;
    }
    auto read = [&](const std::string& name, std::string& error) -> std::optional<std::string> {
        const size_t k = name.size() > 4 && name.compare(name.size() - 4, 4, ".rgb") == 0 ? 2 : 1;
        if (k < parts.size()) return parts[k];
        error = "not in the input";
        return std::nullopt;
    };
    EnviroRead e = readEnviroText("fuzz.e", parts[0], read);
    if (!e.program) return;
    ParseOptions o = parseOptionsFor(FileKind::Cpfg, "");
    o.environmentProgram = e.program;
    ParseResult r = parse("Lsystem: 1\nderivation length: 4\nAxiom: A(1)\nA(x) --> [+(37)f(x)?E(x)][-(20)f(x/2)?E(1,x)]"
                          "[&(30)f(0.3)?E(0,x)?E(2,x)?E(0)?E(x,1,2)]A(x+0.7)\nendlsystem\n", o);
    int n = 0;
    (void)deriveSome(r, 4, n);
}

}  // namespace

// The same bytes as a background scene (cpfg's `background scene:`), which may #include
// "part.dat" (its first half), read and drawn: every message at a line, every point finite.
[[maybe_unused]] void fuzzBackgroundScene(const std::string& input) {
    vlab::BackgroundScene scene;
    vlab::readBackgroundScene(input, "fuzz.dat", scene,
                              [&](const std::string&, const std::string& name, std::string& path, std::string& error) {
                                  path = name;
                                  if (name != "part.dat") error = "no such file";
                                  return name == "part.dat" ? std::optional<std::string>(input.substr(0, input.size() / 2))
                                                            : std::optional<std::string>();
                              });
    for (const auto& p : scene.problems)
        if (p.diagnostic.line < 1) fail("a background scene's message has no line");
    scene.sides = 3 + int(input.size() % 20);
    Geometry g;
    if (drawBackgroundScene(scene, g) > kMaxBackgroundTriangles) fail("too many background triangles");
    for (const glm::vec3& p : g.polygons.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) fail("a background scene's point is not finite");
    if (g.polygons.indices.size() / 3 > kMaxBackgroundTriangles || !g.bounds.empty) fail("the background scene's triangles");
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
#if defined(SPROUT_FUZZ_PARSER)
    (void)parse(input);
#elif defined(SPROUT_FUZZ_EXPR)
    // One expression, with two parameters and a define in scope, compiled and run.
    std::string line = input.substr(0, input.find('\n'));
    SourceLine src{1, line, {}};
    std::vector<std::string> params{"x", "t"};
    std::unordered_map<std::string, double> defines{{"r", 0.7}};
    DiagnosticSink sink;
    if (auto e = compileExpr(line, src, {&params, &defines}, sink)) {
        const double slots[2] = {1.5, -2.0};
        Rng rng(1);
        (void)e->eval(slots, rng);
    }
#elif defined(SPROUT_FUZZ_DERIVE)
    deriveAndDraw(input, 6);
#elif defined(SPROUT_FUZZ_TURTLE)
    // Any module string drawn: the input is the axiom of a system with no rules.
    std::string axiom;
    for (char c : input) axiom += c == '\n' || c == '\r' ? ' ' : c;
    deriveAndDraw("n: 0\nangle: 30\naxiom: " + axiom + "\n", 0);
#elif defined(SPROUT_FUZZ_LPARSER)
    ImportResult r = importLparser(input, "fuzz.ls");
    if (r.ok()) deriveAndDraw(r.text, 4);
#elif defined(SPROUT_FUZZ_FRACTINT)
    for (const auto& s : listFractint(input)) (void)s;
    ImportResult r = importFractint(input, "");
    if (r.ok()) deriveAndDraw(r.text, 4);
#elif defined(SPROUT_FUZZ_CPFG)
    deriveAndDrawCpfg(input, 5);
#elif defined(SPROUT_FUZZ_ENVIRO)
    runEnvironment(input);
#elif defined(SPROUT_FUZZ_VLAB)
    // cpfg's function, contour and curve files, each format read, evaluated and sampled; then
    // func(), curveX(), curveGAL() and @# in a small grammar with what was read.
    auto tables = std::make_shared<CurveTables>();
    FunctionRead f = readFunction(input, "fuzz.func", 100);
    for (double x : {-1.0, 0.0, 0.37, 1.0, 2.0}) (void)f.function(x);
    tables->addFunction(f.function);
    for (const CurveFunction& g : readFunctionSet(input, "fuzz.fset").functions) (void)g(0.5);
    ContourRead c = readContour(input, "fuzz.con");
    if (c.contour) {
        for (int sides : {3, 8, 1024})
            if (c.contour->sampled(sides).size() != size_t(sides) + 1) fail("a contour sampled to the wrong count");
        tables->contours.emplace(1, *c.contour);
    }
    for (const Contour& k : readContourSet(input, "fuzz.cset").contours) (void)k.sampled(8);
    CurveRead crv = readCurve(input, "fuzz.crv", 20);  // a `curve:` line's file
    if (!crv.ok() && crv.diagnostics.empty()) fail("a refused curve says nothing");
    for (double t : {-1.0, 0.0, 0.37, 1.0, 2.0}) (void)crv.curve.at(t);
    tables->curves.push_back(crv.curve);
    ParseOptions o = parseOptionsFor(FileKind::Cpfg, "");
    o.curves = tables;
    ParseResult r = parse("Lsystem: 1\nderivation length: 2\nAxiom: #(1) @!(5) @#(1) @Gs A(0) @Ge\n"
                          "A(t) --> F(func(1, t / 2)) f(curveX(1, t / 2) + curveGAL(1)) A(t + 1)\nendlsystem\n", o);
    int n = 0;
    if (auto d = deriveSome(r, 2, n)) {
        Geometry g;
        interpret(*d->step(n), *r.grammar, {n, d->seed(), nullptr}, g);
    }
    // A VLab object's other files: the same bytes as a view file, an animation file, a
    // material set and a colour map.
    const vlab::ViewFile v = vlab::readViewFile(input);
    for (const auto& d : v.diagnostics)
        if (d.line < 1) fail("a view file's message has no line");
    const vlab::AnimationFile a = vlab::readAnimationFile(input);
    if (a.frames(1000).size() > 100000) fail("too many frames");
    std::string error;
    if (!vlab::readMaterials(input, error) && error.empty()) fail("a refused material set says nothing");
    if (!vlab::readColourMap(input, error) && error.empty()) fail("a refused colour map says nothing");
    fuzzBackgroundScene(input);
    // Each file read is written in its editor's format and read back (issue 52's writers).
    if (f.ok() && f.file) {
        const FunctionRead again = readFunction(writeFunction(*f.file), "fuzz.func", 100);
        if (!again.ok() || !again.file || again.file->points.size() != f.file->points.size()) fail("a written function does not read back");
    }
    if (c.ok() && c.file) {
        const ContourRead again = readContour(writeContour(*c.file), "fuzz.con");
        if (!again.contour || !again.file || again.file->points.size() != c.file->points.size()) fail("a written contour does not read back");
    }
    if (crv.ok()) {
        const CurveRead again = readCurve(writeCurve(crv.curve), "fuzz.crv", 20);
        if (!again.ok() || again.curve.filePoints().size() != crv.curve.filePoints().size()) fail("a written curve does not read back");
    }
    const SurfacePatchesRead sp = readSurfacePatches(input, "fuzz.s");
    if (sp.ok()) {
        const std::string written = writeSurfacePatches(*sp.surface);
        const SurfacePatchesRead again = readSurfacePatches(written, "fuzz.s");
        if (!again.ok() || again.surface->patches.size() != sp.surface->patches.size()) fail("a written surface does not read back");
        if (writeSurfacePatches(*again.surface) != written) fail("a surface written twice differs");
    }
    if (auto m = vlab::readMaterials(input, error)) {
        const std::string written = vlab::writeMaterials(*m);
        auto again = vlab::readMaterials(written, error);
        if (!again || vlab::writeMaterials(*again) != written) fail("a material set written twice differs");
    }
    if (auto m = vlab::readColourMap(input, error))
        if (vlab::writeColourMap(*m) != std::string(input.substr(0, 768))) fail("a colour map does not write back its bytes");
#elif defined(SPROUT_FUZZ_PNG)
    ImportResult r = importPng(input);
    if (r.ok()) (void)parse(r.text);
#elif defined(SPROUT_FUZZ_LPY)
    // An L-Py model's translation (no Python runs): every line keeps its number.
    lpy::Translation t = lpy::translate(input);
    std::string text;  // as the translation reads it: a carriage return is no line break
    for (char c : input)
        if (c != '\r') text += c;
    size_t lines = 1, mainLines = 0, tag = text.find("###### INITIALISATION ######");
    for (size_t k = 0; k < std::min(tag, text.size()); ++k) lines += text[k] == '\n';
    for (char c : t.mainCode) mainLines += c == '\n';
    if (tag == std::string::npos && mainLines != lines) fail("the translation lost or added lines");
    (void)detectFileKind("model.lpy", input);
    // The file's bytes decoded as L-Py's Python decodes them: UTF-8, its lines kept.
    const std::string utf8 = lpy::modelTextAsUtf8(input);
    if (std::count(utf8.begin(), utf8.end(), '\n') != std::count(input.begin(), input.end(), '\n'))
        fail("decoding a model file lost or added lines");
    for (size_t k = 0; k < utf8.size();) {
        const unsigned char c = static_cast<unsigned char>(utf8[k]);
        const size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        if (n == 0 || k + n > utf8.size()) fail("a decoded model file is not UTF-8");
        for (size_t j = 1; j < n; ++j)
            if ((static_cast<unsigned char>(utf8[k + j]) & 0xC0) != 0x80) fail("a decoded model file is not UTF-8");
        k += n;
    }
    // The model's curves as the viewer's curve editor reads them: each list where it was read,
    // a point moved written back in place (the text before the list kept) and read again.
    const std::string asText(input);
    const std::vector<LpyCurve> curves = lpyCurves(asText);
    for (const LpyCurve& c : curves) {
        if (c.begin >= c.end || c.end > asText.size() || asText[c.begin] != '[' || asText[c.end - 1] != ']' || c.points.size() < 2)
            fail("a curve's list is not where it was read");
        std::vector<std::array<double, 3>> pts = c.points;
        pts[0][0] = pts[0][0] / 2 + 0.25;
        const std::string moved = setLpyCurvePoints(asText, c, pts);
        if (moved.compare(0, c.begin, asText, 0, c.begin) != 0) fail("moving a curve point changed the text before its list");
        if (lpyCurves(moved).size() != curves.size()) fail("moving a curve point changed which curves are read");
    }
    // Its materials, patches and scalars as the panel's editors read and write them.
    const std::vector<LpyMaterial> materials = lpyMaterials(asText);
    for (const LpyMaterial& m : materials) {
        if (!m.texture.empty()) continue;
        LpyMaterial v = m;
        v.diffuse = 1.5, v.ambient = {1, 2, 3};
        std::string moved = setLpyMaterial(asText, m, LpyMaterial::Diffuse, v);
        if (lpyMaterials(moved).size() != materials.size()) fail("setting a material's diffuse changed which materials are read");
        moved = setLpyMaterial(asText, m, LpyMaterial::Ambient, v);
        if (lpyMaterials(moved).size() != materials.size()) fail("setting a material's ambient changed which materials are read");
    }
    const std::vector<LpyPatch> patches = lpyPatches(asText);
    for (const LpyPatch& p : patches) {
        auto rows = p.rows;
        rows[0][0][0] += 0.5;
        if (lpyPatches(setLpyPatchPoints(asText, p, rows)).size() != patches.size()) fail("moving a patch point changed which patches are read");
    }
    // (their list is read two ways, lpyScalars' and the editor's; only that neither breaks)
    for (const LpyScalar& sc : lpyScalars(asText)) {
        std::string error;
        (void)lpyScalars(removeLpyScalar(asText, sc.name, error));
        (void)lpyScalars(renameLpyScalar(asText, sc.name, "fuzz_renamed", error));
    }
    {
        LpyScalar added;
        added.name = "fuzz_added";
        std::string error;
        (void)lpyScalars(addLpyScalar(asText, added, error));
    }
#elif defined(SPROUT_FUZZ_IMAGE)
    // A texture image's bytes (PNG, JPEG, SGI): read whole, or refused with a reason.
    const sprout::mesh::TextureImage image = sprout::mesh::decodeImage(input);
    if (image.error.empty()) {
        if (image.width <= 0 || image.height <= 0) fail("an image read without a size");
        if (image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4) fail("an image's pixels are not its size");
    } else if (!image.rgba.empty() && image.format != "jpeg") {
        fail("a refused image kept pixels");
    }
#else
#error "define one SPROUT_FUZZ_<TARGET>"
#endif
    return 0;
}
