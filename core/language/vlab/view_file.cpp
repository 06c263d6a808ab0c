// A VLab object's view file, read as VLab's cpfg reads it (interpret.c, ReadViewData; lights
// irisGL.c read_light; textures textures.c read_texture).
//
// Index of this file:
//   [SECTION] The commands cpfg accepts, and reading a command's values
//   [SECTION] The turtle's commands
//   [SECTION] The camera's and the lights' commands
//   [SECTION] Commands that name files, and those kept as written
//   [SECTION] The file's lines

#include "core/language/vlab/view_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <type_traits>

namespace sprout::vlab {

// [SECTION] The commands cpfg accepts, and reading a command's values

const std::vector<std::string>& viewFileCommands() {
    static const std::vector<std::string> names = {
        "angle factor:", "angle increment:", "initial color:", "color increment:", "initial line width:",
        "line width increment:", "viewpoint:", "view reference point:", "twist:", "projection:",
        "front distance:", "back distance:", "scale factor:", "z buffer:", "cue range:", "shade mode:",
        "light direction:", "diffuse reflection:", "surface ambient:", "surface diffuse:", "line:", "surface:",
        "box:", "background color:", "ambient light:", "font:", "polygonization level:", "tropism direction:",
        "initial elasticity:", "elasticity increment:", "blob:", "tropism:", "torque:", "light:", "texture:",
        "render mode:", "line style:", "tapered lines:", "contour sides:", "contour:", "viewing angle:",
        "background scene:", "twist of cylinders:", "interpretation step:", "interpretation past %:",
        "tsurface:", "rayshade objects:", "rayshade scale:", "initial scale:", "scale multiplier:",
        "environment display:", "function:", "curve:", "antialiasing:", "function set:", "min zoom:",
        "max zoom:", "generate on view change:", "winfont:", "concave polygons:", "shadow map:", "PS linecap:"};
    return names;
}

namespace {

// A command's values: numbers separated by spaces or commas, words, the rest of the line.
struct Values {
    std::string_view text;
    size_t pos = 0;

    void skip(bool commas) {
        while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t' || text[pos] == '\r' || (commas && text[pos] == ',')))
            ++pos;
    }
    std::optional<double> number() {
        skip(true);
        size_t at = pos + (pos < text.size() && text[pos] == '+' ? 1 : 0);
        double v = 0;
        auto [end, ec] = std::from_chars(text.data() + at, text.data() + text.size(), v);
        if (ec != std::errc() || !std::isfinite(v)) return std::nullopt;
        pos = size_t(end - text.data());
        return v;
    }
    std::optional<Vec3> vec3() {
        Vec3 v{};
        for (double& x : v) {
            auto n = number();
            if (!n) return std::nullopt;
            x = *n;
        }
        return v;
    }
    std::string word() {
        skip(false);
        const size_t begin = pos;
        while (pos < text.size() && text[pos] != ' ' && text[pos] != '\t' && text[pos] != '\r') ++pos;
        return std::string(text.substr(begin, pos - begin));
    }
    std::string rest() {
        skip(false);
        std::string_view r = text.substr(std::min(pos, text.size()));
        while (!r.empty() && (r.back() == ' ' || r.back() == '\t' || r.back() == '\r')) r.remove_suffix(1);
        pos = text.size();
        return std::string(r);
    }
    bool atEnd() {
        skip(false);
        return pos >= text.size();
    }
};

// What reading one command needs: the file being filled, the line, how to say what is wrong.
struct Command {
    ViewFile& out;
    const std::string& name;  // with its ':'
    Values& values;
    int line;
    int col;  // of the values

    void expected(const std::string& what) const {
        out.diagnostics.push_back({line, col, "'" + name + "' expects " + what + "; found '" + std::string(values.text) + "'", Severity::Error});
    }
    void warn(const std::string& message) const { out.diagnostics.push_back({line, col, message, Severity::Warning}); }
    // One number into `into`, or an error naming what was expected.
    template <class T>
    bool one(T& into, const char* what = "a number") const {
        auto n = values.number();
        if (!n) return expected(what), false;
        if constexpr (std::is_integral_v<T>) {
            // A whole number from the file: far out of range is the nearest end, never UB.
            if (!std::isfinite(*n)) return expected(what), false;
            into = T(std::clamp(*n, -1e9, 1e9));
        } else {
            into = T(*n);
        }
        return true;
    }
    bool three(Vec3& into) const {
        auto v = values.vec3();
        if (!v) return expected("three numbers x,y,z"), false;
        into = *v;
        return true;
    }
    bool onOff(bool& into) const {
        const std::string w = values.word();
        if (w.empty()) return expected("on or off"), false;
        into = w.rfind("on", 0) == 0;
        return true;
    }
};

Vec3 unit(Vec3 v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return n > 0 ? Vec3{v[0] / n, v[1] / n, v[2] / n} : v;
}

// [SECTION] The turtle's commands

// `tropism: T: 0 1 0 A: 90 E: 0.1 S: 0.05` (movements.c): fields by their first letter.
void movementCommand(const Command& c) {
    Movement m;
    m.torque = c.name == "torque:";
    m.line = c.line;
    std::vector<std::string> words;
    for (std::string w = c.values.rest(), cur; char ch : w + " ") {
        if (ch == ' ' || ch == '\t' || ch == ':' || ch == ',') {
            if (!cur.empty()) words.push_back(cur), cur.clear();
        } else {
            cur += ch;
        }
    }
    double intensity = 1;
    bool direction = false, intensityGiven = false;
    auto number = [&](size_t& k, double& into) {
        if (k + 1 >= words.size()) return false;
        char* end = nullptr;
        const double v = std::strtod(words[k + 1].c_str(), &end);
        if (end == words[k + 1].c_str() || *end != '\0' || !std::isfinite(v)) return false;
        into = v;
        ++k;
        return true;
    };
    for (size_t k = 0; k < words.size(); ++k) {
        const char f = words[k][0];
        bool ok = true;
        if (f == 'T') {
            for (double& x : m.direction) ok = ok && number(k, x);
            direction = ok;
        } else if (f == 'I') {
            ok = intensityGiven = number(k, intensity);
        } else if (f == 'A') {
            ok = number(k, m.angle);
        } else if (f == 'E') {
            ok = number(k, m.elasticity);
        } else if (f == 'S') {
            ok = number(k, m.step);
        } else {
            return c.warn("unknown field '" + words[k] + "' (cpfg reads T:, I:, A:, E: and S:): the line is left out, as cpfg leaves it");
        }
        if (!ok) return c.expected("'T: x y z' and then I:, A:, E: or S: with a number each");
    }
    const double n = std::sqrt(m.direction[0] * m.direction[0] + m.direction[1] * m.direction[1] + m.direction[2] * m.direction[2]);
    if (!direction || n == 0) return c.expected("a direction 'T: x y z' that is not 0 0 0");
    // cpfg: the direction made unit, or with I: its length I, at most 1 (as long as T's)
    const double scale = intensityGiven ? std::clamp(intensity / n, -1.0, 1.0) : 1 / n;
    for (double& x : m.direction) x *= scale;
    if (c.out.movements.size() >= 10) return c.warn("cpfg keeps at most 10 tropisms and torques: this one is left out");
    c.out.movements.push_back(m);
}

bool turtleCommand(const Command& c) {
    ViewFile& o = c.out;
    const std::string& n = c.name;
    if (n == "angle factor:") {
        double f = 0;
        if (c.one(f)) {
            if (f == 0) return c.expected("a number of turns in a circle, not 0"), true;
            o.angleIncrement = 360.0 / f;
        }
    } else if (n == "angle increment:") {
        double a = 0;
        if (c.one(a)) o.angleIncrement = a;
    } else if (n == "initial color:") {
        int k = 0;
        if (c.one(k, "a colour index")) o.initialColour = k;
        if (auto b = c.values.number(); b && std::isfinite(*b)) o.initialColourBack = int(std::clamp(*b, -1e9, 1e9));
    } else if (n == "color increment:") {
        c.one(o.colourIncrement, "a colour index step");
        if (auto b = c.values.number(); b && std::isfinite(*b)) o.colourIncrementBack = int(std::clamp(*b, -1e9, 1e9));
    } else if (n == "initial line width:") {
        double w = 0;
        if (!c.one(w, "a width, then optionally 'pixels' or 'polygons'")) return true;
        o.lineWidth = w;
        o.lineStyle = LineStyle::Polygon;  // as cpfg: a width without a word is a polygon's
        const std::string word = c.values.word();
        if (!word.empty() && word[0] == 'p' && word != "polygons" && word != "polygon") o.lineStyle = LineStyle::Pixel;
        if (!word.empty() && word[0] == 's') o.lineStyle = LineStyle::Cylinder;
        o.lineStyleSet = true;
    } else if (n == "line width increment:") {
        c.one(o.widthIncrement);
    } else if (n == "line style:") {
        const std::string w = c.values.word();
        if (w == "pixel" || w == "1") o.lineStyle = LineStyle::Pixel;
        else if (w == "polygon" || w == "2") o.lineStyle = LineStyle::Polygon;
        else if (w == "cylinder" || w == "3") o.lineStyle = LineStyle::Cylinder;
        else return c.warn("unknown line style '" + w + "' (expected pixel, polygon or cylinder): cpfg keeps the one it had"), true;
        o.lineStyleSet = true;
    } else if (n == "tropism direction:") {
        Vec3 v{};
        if (c.three(v)) o.tropismDirection = unit(v);
    } else if (n == "tropism:" || n == "torque:") {
        return movementCommand(c), true;
    } else if (n == "initial elasticity:") {
        c.one(o.elasticity);
    } else if (n == "elasticity increment:") {
        c.one(o.elasticityIncrement);
    } else if (n == "twist of cylinders:") {
        c.onOff(o.twistOfCylinders);
    } else if (n == "tapered lines:") {
        c.onOff(o.taperedLines);
    } else if (n == "contour sides:") {
        if (c.one(o.contourSides, "a number of sides")) o.contourSides = std::max(o.contourSides, 3);
    } else if (n == "polygonization level:") {
        int level = 0;
        if (c.one(level, "a level")) o.contourSides = std::max(3, int(std::lround(std::pow(2.0, std::clamp(level, 0, 12) + 1))));
    } else if (n == "initial scale:") {
        if (c.one(o.initialScale) && o.initialScale == 0) o.initialScale = 1;
    } else if (n == "scale multiplier:") {
        if (c.one(o.scaleMultiplier) && o.scaleMultiplier == 0) o.scaleMultiplier = 1;
    } else if (n == "interpretation step:") {
        if (c.one(o.interpretationStep, "a step") && (o.interpretationStep < -1 || o.interpretationStep == 0)) o.interpretationStep = -1;
    } else if (n == "interpretation past %:") {
        o.interpretationPastCut = c.values.word().rfind("off", 0) != 0;
    } else if (n == "render mode:") {
        static const char* modes[] = {"wireframe", "filled", "flat", "interpolated", "shaded", "fast", "shadows"};
        const std::string w = c.values.word();
        auto it = std::find(std::begin(modes), std::end(modes), w);
        if (it != std::end(modes)) o.renderMode = w;
        else if (w.size() == 1 && w[0] >= '1' && w[0] <= '7') o.renderMode = modes[w[0] - '1'];
        else c.warn("unknown render mode '" + w + "': cpfg keeps the default (filled)");
    } else if (n == "shade mode:") {
        c.one(o.shadeMode, "a shade mode");
    } else {
        return false;
    }
    return true;
}

// [SECTION] The camera's and the lights' commands

bool cameraCommand(const Command& c) {
    ViewFile& o = c.out;
    const std::string& n = c.name;
    if (n == "viewpoint:") c.three(o.viewpoint);
    else if (n == "view reference point:") c.three(o.reference);
    else if (n == "twist:") {
        // cpfg reads an integer; its view-up vector turns by a tenth of a degree for each (interpret.c)
        c.one(o.twist, "a number");
    } else if (n == "projection:") {
        const std::string w = c.values.word();
        if (w.empty()) return c.expected("parallel or perspective"), true;
        if (w.rfind("perspective", 0) == 0) o.perspective = true;
        else if (w.rfind("parallel", 0) == 0) o.perspective = false;
        else c.warn("unknown projection '" + w + "': parallel assumed, as cpfg does");
    } else if (n == "viewing angle:") c.one(o.viewingAngle);
    else if (n == "front distance:") c.one(o.front);
    else if (n == "back distance:") c.one(o.back);
    else if (n == "scale factor:") {
        if (c.one(o.scale) && o.scale == 0) o.scale = 1;
    } else if (n == "z buffer:") c.onOff(o.zBuffer);
    else if (n == "cue range:") c.one(o.cueRange, "a range");
    else if (n == "min zoom:") c.one(o.minZoom);
    else if (n == "max zoom:") c.one(o.maxZoom);
    else if (n == "antialiasing:") c.onOff(o.antialiasing);
    else if (n == "box:") {
        // `box: x: a,b y: c,d z: e,f`
        std::array<Vec3, 2> b{};
        for (int axis = 0; axis < 3; ++axis) {
            const std::string label = c.values.word();
            auto lo = c.values.number(), hi = c.values.number();
            if (label != std::string(1, char('x' + axis)) + ":" || !lo || !hi)
                return c.expected("x: min,max y: min,max z: min,max"), true;
            b[0][size_t(axis)] = *lo;
            b[1][size_t(axis)] = *hi;
        }
        o.box = b;
    } else if (n == "light direction:") {
        if (c.three(o.lightDirection)) {
            o.lightDirection = unit(o.lightDirection);
            o.lightDirectionSet = true;
        }
    } else if (n == "diffuse reflection:") c.one(o.diffuseReflection);
    else if (n == "surface ambient:") c.one(o.surfaceAmbient);
    else if (n == "surface diffuse:") c.one(o.surfaceDiffuse);
    else if (n == "background color:" || n == "ambient light:") {
        Vec3 v{};
        if (c.three(v)) (n == "ambient light:" ? o.ambientLight : o.backgroundColour) = v;
    } else if (n == "light:") {
        // `light: V: x y z A: r g b D: r g b S: r g b` (O: a position instead of V:)
        Light l;
        l.line = c.line;
        std::string text = c.values.rest();
        std::replace(text.begin(), text.end(), ':', ' ');  // `V: 1 2 3`, `V:1 2 3` and `D 1 1 1` alike
        Values v{text};
        for (std::string key = v.word(); !key.empty(); key = v.word()) {
            Vec3* into = key[0] == 'V' || key[0] == 'O' ? &l.vector : key[0] == 'A' ? &l.ambient : key[0] == 'D' ? &l.diffuse : key[0] == 'S' ? &l.specular : nullptr;
            if (key[0] == 'O') l.directional = false;
            if (!into) continue;  // spot, attenuation: read by cpfg's GL only
            auto x = v.vec3();
            if (!x) return c.expected("V: x,y,z (or O:), then optionally A:, D:, S: with three numbers each"), true;
            *into = *x;
        }
        o.lights.push_back(l);
    } else {
        return false;
    }
    return true;
}

// [SECTION] Commands that name files, and those kept as written

bool fileCommand(const Command& c) {
    const std::string& n = c.name;
    FileReference f;
    f.command = n.substr(0, n.size() - 1);
    f.line = c.line;
    if (n == "surface:" || n == "line:" || n == "tsurface:") {
        const std::string id = c.values.word();
        f.file = c.values.word();
        if (id.size() != 1 || f.file.empty()) return c.expected("a letter, a file and a size"), true;
        f.id = id[0];
        while (auto v = c.values.number()) f.numbers.push_back(*v);
        if (f.numbers.empty()) return c.expected("a letter, a file and a size"), true;
    } else if (n == "contour:") {
        auto id = c.values.number();
        f.file = c.values.word();
        if (!id || f.file.empty()) return c.expected("a contour's number and its file"), true;
        f.numbers.push_back(*id);
    } else if (n == "background scene:") {
        // cpfg (ReadBackgroundSceneFile): the rest of the line, files separated by spaces,
        // commas or semicolons, read one after the other.
        const std::string rest = c.values.rest();
        for (size_t i = 0; i < rest.size();) {
            const size_t end = std::min(rest.find_first_of(" \t,;", i), rest.size());
            if (end > i) {
                f.file = rest.substr(i, end - i);
                c.out.files.push_back(f);
            }
            i = end + 1;
        }
        if (f.file.empty()) c.expected("a file");
        return true;
    } else if (n == "function:" || n == "curve:" || n == "function set:" || n == "blob:") {
        f.file = c.values.word();
        if (f.file.empty()) return c.expected("a file"), true;
        while (auto v = c.values.number()) f.numbers.push_back(*v);
    } else if (n == "texture:") {
        // `texture: F: bark.png E: m R: 1.6 H: l L: n`: the file after F:
        std::string options;
        for (std::string w = c.values.word(); !w.empty(); w = c.values.word()) {
            if (w == "F:" || w == "F") f.file = c.values.word();
            else if (w.rfind("F:", 0) == 0) f.file = w.substr(2);
            else options += (options.empty() ? "" : " ") + w;
        }
        if (f.file.empty()) return c.expected("F: and a file"), true;
        f.options = options;
    } else {
        return false;
    }
    c.out.files.push_back(std::move(f));
    return true;
}

// Commands cpfg reads that concern its own window, its other renderers or its environment
// programs: kept as written.
bool keptCommand(const Command& c) {
    static const char* kept[] = {"font:", "winfont:", "rayshade objects:", "rayshade scale:",
                                 "environment display:", "generate on view change:", "concave polygons:",
                                 "shadow map:", "PS linecap:"};
    for (const char* k : kept)
        if (c.name == k) {
            c.out.others.push_back({c.name.substr(0, c.name.size() - 1), c.values.rest(), c.line});
            return true;
        }
    return false;
}

// [SECTION] The file's lines

// The text without comments (/* */ over lines too, and //), each line where it was.
std::string withoutComments(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    bool block = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char ch = text[i];
        if (block) {
            if (ch == '*' && i + 1 < text.size() && text[i + 1] == '/') block = false, ++i, out += ' ';
            else if (ch == '\n') out += '\n';
        } else if (ch == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            block = true;
            ++i;
        } else if (ch == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
        } else {
            out += ch;
        }
    }
    return out;
}

std::string collapsed(std::string_view s) {
    std::string out;
    for (char ch : s) {
        const bool space = ch == ' ' || ch == '\t' || ch == '\r';
        if (space && (out.empty() || out.back() == ' ')) continue;
        out += space ? ' ' : ch;
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

}  // namespace

ViewFile readViewFile(std::string_view text) {
    ViewFile out;
    const std::string clean = withoutComments(text);
    int number = 0;
    for (size_t start = 0; start <= clean.size();) {
        size_t end = clean.find('\n', start);
        if (end == std::string::npos) end = clean.size();
        const std::string_view line = std::string_view(clean).substr(start, end - start);
        start = end + 1;
        ++number;
        const std::string trimmed = collapsed(line);
        if (trimmed.empty()) continue;
        if (trimmed[0] == '#') {
            out.diagnostics.push_back({number, 1, "a preprocessor line ('" + trimmed + "') is not read in a view file", Severity::Warning});
            continue;
        }
        const size_t colon = line.find(':');
        if (colon == std::string_view::npos) {
            out.diagnostics.push_back({number, 1, "'" + trimmed + "' is no view-file command (expected 'name: value')", Severity::Warning});
            continue;
        }
        const std::string name = collapsed(line.substr(0, colon)) + ":";
        const size_t first = line.find_first_not_of(" \t");
        Values values{line.substr(colon + 1)};
        Command c{out, name, values, number, int(colon) + 2};
        if (turtleCommand(c) || cameraCommand(c) || fileCommand(c) || keptCommand(c)) continue;
        std::vector<std::string> names;
        for (const std::string& k : viewFileCommands()) names.push_back(k);
        const std::string near = closestMatch(name, names);
        out.diagnostics.push_back({number, int(first) + 1,
                                   "unknown view-file command '" + name + "' (cpfg skips it)" + (near.empty() ? "" : "; did you mean '" + near + "'?"),
                                   Severity::Warning});
    }
    return out;
}

}  // namespace sprout::vlab
