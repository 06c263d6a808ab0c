#pragma once
// cpfg's FUNCTIONS and CONTOURS: the files VLab's editors write (funcedit: `.func`, gallery:
// `.fset` and `.cset`, cuspy: `.con`), read the way cpfg reads them, and evaluated the way cpfg
// evaluates them, so that `func(id, x)` gives the numbers cpfg's derivation gets and `@#(n)`
// the cross-section cpfg draws.
//
//   Functions (cpfg/splinefun.cpp): a cubic B-spline through the control points (x, y) (each
//   repeated by its multiplicity), its x increasing from 0 to 1. func(id, x) clamps x to
//   [0, 1]; with `samples:` (or a view file's count) over 2 it is a table of that many values,
//   linearly interpolated, else the curve itself, found by bisection on x to 0.001. `flip:` is
//   the editor's view only: cpfg ignores it (funcedit writes the points unflipped).
//   Contours (cpfg/general.c): a uniform cubic B-spline through the control points (closed:
//   wrapping round), resampled to `sides` points equally spaced along its length (cpfg's
//   `contour sides:`, 8 by default); a closed contour is turned so that its first point lies
//   on the x axis. cpfg draws x along the turtle's up and y along its right (-left).
//   Curves (cpfg/curveXYZ.cpp, the `curve:` lines' files, cuspy's `version: 1.4`): control
//   points in 3D, a B-spline (open, closed, end-point or phantom), Bezier segments or a Bezier
//   surface; curveX/Y/Z(id, t) is the point at the fraction t of its length (measured along
//   `samples` points of it), curveGAL(id) that length.
//
// Every reader returns what it read and the problems found, each at its line and column with
// what was expected there; it never throws, and nothing in a file can make it loop long.
// Includes only core/base.
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sprout {

// A problem in a function or contour file: "FILE:line:col: message" by text().
struct CurveFileDiagnostic {
    std::string file;
    int line = 0;  // 1-based; 0: the file as a whole (it cannot be read)
    int col = 0;   // 1-based
    std::string message;
    bool warning = false;  // read anyway (an unsupported detail cpfg skips too)
    std::string text() const;
};

// [SECTION] Functions

class CurveFunction {
public:
    // cpfg's default when a file cannot be read: 0 everywhere (points (0,0) x3 and (1,0)).
    CurveFunction();
    // `points` with their multiplicities already expanded (at least 4); `samples` > 2: a table.
    CurveFunction(std::string name, std::vector<std::array<double, 2>> points, int samples);

    const std::string& name() const { return m_name; }  // `name:` (the file's stem for the old format)
    int samples() const { return m_samples; }           // > 2: evaluated from a table
    const std::vector<std::array<double, 2>>& points() const { return m_points; }
    double operator()(double x) const;  // cpfg's SplineFunction::GetValue
    double curveValue(double x) const;  // the curve itself (bisection), as the table is made

private:
    std::array<double, 2> point(double d) const;
    std::string m_name;
    std::vector<std::array<double, 2>> m_points;
    int m_samples = 0;
    std::vector<double> m_table;
};

// A function as its file keeps it, what funcedit edits and writes: the points with their
// multiplicities (x, y, multiplicity), not expanded.
struct FunctionFile {
    std::string name;
    int samples = 10;       // `samples:` (the first format has none: funcedit's 10)
    bool flip = false;      // `flip:` (funcedit's view: x and y swapped on screen)
    bool original = false;  // read from the first format (`range:`)
    std::vector<std::array<double, 3>> points;
    // What cpfg evaluates: the points expanded, `samples` (the view file's for the first format).
    CurveFunction function(int viewSamples = -1) const;
};

struct FunctionRead {
    CurveFunction function;  // the default (0 everywhere) when the file could not be read, as cpfg
    std::optional<FunctionFile> file;  // as the file keeps it, when it could be read
    std::vector<CurveFileDiagnostic> diagnostics;
    bool ok() const;
};
struct FunctionSetRead {
    std::vector<CurveFunction> functions;  // func(i) is functions[i-1]; names from `name:`
    std::vector<FunctionFile> files;       // the same, as the set keeps them
    std::vector<CurveFileDiagnostic> diagnostics;
    bool ok() const;
};

// A `.func` file: `fver 1 1` (name:, samples:, flip:, points: n, then `x y [multiplicity]`
// lines) or the first format (`range: 0 1`, `points: n`, `x y` lines). `samples` is the count
// of the view file's `function: FILE SAMPLES` line (-1 when it has none): the first format
// uses it, `fver 1 1` its own `samples:`.
FunctionRead readFunction(std::string_view text, const std::string& fileName, int samples);
FunctionRead loadFunction(const std::filesystem::path& path, int samples);
// A `.fset` file (`funcgalleryver 1 1`, `items: n`, n functions in `fver 1 1`).
FunctionSetRead readFunctionSet(std::string_view text, const std::string& fileName);
FunctionSetRead loadFunctionSet(const std::filesystem::path& path);
// The text funcedit saves (funcedit/model.cpp, Model::Save): always `fver 1 1`, `%f %f %d`
// points (a first-format file is written in it, as funcedit does). The gallery's set
// (gallery.cpp, saveFuncSet): `funcgalleryver 1 1`, `items: n`, then each function so.
std::string writeFunction(const FunctionFile& f);
std::string writeFunctionSet(const std::vector<FunctionFile>& set);

// [SECTION] Contours

struct Contour {
    std::string name;
    bool closed = true;
    int dim = 3;  // 2 for the first format's 2D points
    std::vector<std::array<float, 3>> points;  // control points, multiplicities expanded
    // cpfg's MakeContour: `sides` (3..1024) points equally spaced along the curve in x y;
    // closed: sides + 1 points, the last the first; open: sides + 1 points, end to end.
    std::vector<std::array<float, 3>> sampled(int sides) const;
};

// A contour as its file keeps it, what cuspy edits and writes: points (x, y, z, multiplicity)
// not expanded; a first-format file's repeated points joined, as cuspy reads them.
struct ContourFile {
    std::string name;
    int version = 103;       // 101, 102, 103 (`cver 1 n`); 0: the first format
    bool closed = true;
    bool endpoint = false;   // `type: ?e` (cpfg draws it as a regular one)
    int samples = 8;         // cuspy's `samples:` (1.3; cuspy's 8 otherwise)
    int dim = 3;             // 2 for the first format's 2D points
    std::vector<std::array<double, 4>> points;
    Contour contour() const;  // the points expanded, as cpfg uses them
};

struct ContourRead {
    std::optional<Contour> contour;  // none when the file cannot be read (cpfg: the circle)
    std::optional<ContourFile> file;
    std::vector<CurveFileDiagnostic> diagnostics;
    bool ok() const;
};
struct ContourSetRead {
    std::vector<Contour> contours;  // in file order, named by `name:`
    std::vector<ContourFile> files;
    std::vector<CurveFileDiagnostic> diagnostics;
    bool ok() const;
};

// A `.con` file: `cver 1 1` / `1 2` / `1 3` (name:, points: n total, type: open|closed or
// or|oe|cr|ce, samples:, then `x y z multiplicity` lines) or the first format (`n dim
// closed|open`, then n points of dim coordinates).
ContourRead readContour(std::string_view text, const std::string& fileName);
ContourRead loadContour(const std::filesystem::path& path);
// A `.cset` file (`contourgalleryver 1 1`, `items: n`, n contours in `cver`).
ContourSetRead readContourSet(std::string_view text, const std::string& fileName);
ContourSetRead loadContourSet(const std::filesystem::path& path);
// The text cuspy saves (cuspy/model.cpp, Model::Save): always `cver 1 3`, `points: n total`,
// `type: [co][re]`, `samples:`, `%f %f %f %d` points (z as read: cuspy writes 0, cpfg reads it). The
// gallery's set: `contourgalleryver 1 1`, `items: n`, then each contour so.
std::string writeContour(const ContourFile& c);
std::string writeContourSet(const std::vector<ContourFile>& set);

// [SECTION] Curves

// A `curve:` line's curve: cpfg's CCurveXYZ, evaluated in its order of operations.
class CurveXYZ {
public:
    // cpfg's `type:` (bspline, bspline-closed, bspline-endpoint, bspline-phantom, bezier,
    // bezier-surface; any other word is bspline).
    enum class Type : std::uint8_t { BSpline, Closed, Endpoint, Phantom, Bezier, BezierSurface };
    struct Point {
        std::array<double, 3> p{0, 0, 0};
        int multiplicity = 1;
    };
    static constexpr int kMaxSamples = 100000;

    // cpfg's curve when its file cannot be read (CCurveXYZ's first curve, kept): the Bezier
    // surface of a 4 x 4 grid of points from -1.5 to 1.5.
    explicit CurveXYZ(int samples = 100);
    // `points` as the file gives them (cpfg's createPPoints repeats each by its multiplicity,
    // adds the closed curve's first three again or the phantom ends); `samples` (2 ..
    // kMaxSamples, else the nearest) points along it measure its length.
    CurveXYZ(std::string name, Type type, const std::vector<Point>& points, int samples);

    const std::string& name() const { return m_name; }
    Type type() const { return m_type; }
    int samples() const { return m_samples; }
    const std::vector<std::array<double, 3>>& points() const { return m_points; }  // expanded
    const std::vector<Point>& filePoints() const { return m_filePoints; }          // as the file gives them
    double length() const { return m_length; }  // curveGAL: the polyline through the samples
    // curveX/Y/Z(id, t) (cpfg's CurveCXS, calcAValue): t clamped to [0, 1] is a fraction of
    // the length, found between two samples and interpolated there; NaN gives NaN.
    std::array<double, 3> at(double t) const;
    // The curve at its parameter t in [0, 1] (cpfg's calcPValue(0, t, s)); s: across a surface.
    std::array<double, 3> atParameter(double t, double s = 0) const;

private:
    std::string m_name;
    Type m_type = Type::BSpline;
    int m_samples = 100;
    std::vector<std::array<double, 3>> m_points;
    std::vector<Point> m_filePoints;
    std::vector<double> m_arc;  // the length up to each sample over the whole (cpfg's _l)
    double m_length = 0;
};

struct CurveRead {
    CurveXYZ curve;  // as cpfg has it: read up to the first problem (unread points at 0, 0, 0)
    std::vector<CurveFileDiagnostic> diagnostics;
    bool ok() const;
};

// A curve file as cpfg's CCurveXYZ::readCurve reads it, line by line: `//` comments,
// `version:`, `contact:`, `end:`, `heading:`, `up:`, `size:`, `range:` (read, not used),
// `points: N` (a curve of N points; inside one, the curve of the point before it, which cpfg
// keeps but does not draw), `dimension: D` (2 to 4 numbers a point: x y [z [multiplicity]]),
// `type:`, then the points; other lines with a ':' are skipped. Reading stops at the first
// problem, as cpfg's does. `samples` is the `curve:` line's count (cpfg's 100 without one).
// A file that cannot be read is cpfg's default curve, CurveXYZ(samples), and a diagnostic.
CurveRead readCurve(std::string_view text, const std::string& fileName, int samples);
CurveRead loadCurve(const std::filesystem::path& path, int samples);
// A curve as cuspy writes a `version: 1.4` file (cuspy/model.cpp): its fixed header (contact,
// end, heading, up, size and range, which cpfg reads and does not use), `points: n`,
// `dimension: 4`, the type, then `x y z multiplicity` lines (`%f`, z as `%g`).
std::string writeCurve(const CurveXYZ& c);

// [SECTION] What a grammar uses

// The functions of curves and function files a grammar calls (Op::Func's `fn`).
enum class CurveCall : std::uint8_t { Func, CurveX, CurveY, CurveZ, CurveLength };
// func, curveX, curveY, curveZ, curveGAL; nullopt for another name.
std::optional<CurveCall> curveCallNamed(std::string_view name);

// The functions, curves and contours a cpfg grammar runs with (from its view file's
// `function:`, `function set:`, `curve:`, `contour:` and `contour sides:` lines), kept by the
// Grammar (ParseOptions::curves) so that func(), curveX() ... and @# use them at derive and
// draw time. Immutable once parsed.
struct CurveTables {
    std::vector<CurveFunction> functions;  // func(id, x): functions[id - 1]
    // cpfg defines each function of a function set by its name (`-DNAME=id`), but only while
    // the view file's last function line is a `function set:`.
    bool functionsFromSet = false;
    std::map<int, Contour> contours;  // by the id of `contour: ID FILE` (0 is cpfg's circle)
    int contourSides = 8;             // `contour sides:`

    // A `function:` line: appended (its id is the count after it), names no longer defined.
    void addFunction(CurveFunction f);
    // A `function set:` line: the set replaces every function read before (cpfg resets them).
    void setFunctionSet(std::vector<CurveFunction> set);
    // The id a name stands for in expressions (a function set's function), or 0.
    int functionId(std::string_view name) const;
    std::vector<std::string> functionNames() const;
    std::vector<CurveXYZ> curves;     // curveX(id, t): curves[id - 1], in the `curve:` lines' order

    // cpfg's func(id, x): (int)id; out of range is 0 (cpfg warns and gives 0).
    double func(double id, double x) const;
    // func(id, x), curveX/Y/Z(id, x) or curveGAL(id) (x unused): (int)id, from 1; an id out
    // of range gives 0, as in cpfg.
    double call(CurveCall c, double id, double x) const;
    // What is wrong with a constant id (none, too big ...) for `c`, as a warning; "" when it is
    // one of them.
    std::string idProblem(CurveCall c, double id) const;
    // The cross-section of `@#(id)` as Sprout's generalized cylinder takes it (x along the
    // turtle's left, y along its up, the radius one unit): cpfg's points at `sides` (0:
    // contourSides), (x, y) -> (-y, x). Empty for an id with no contour (cpfg's circle).
    std::vector<std::array<float, 2>> section(int id, int sides = 0) const;
};

}  // namespace sprout
