#include "core/language/vlab/background_scene.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <optional>

#include "core/base/read_file.hpp"

namespace sprout::vlab {
namespace {

using C = BackgroundCommand;

constexpr size_t kMaxValues = 1'000'000;
constexpr size_t kMaxProblems = 64;
constexpr int kStackSize = 50;  // cpfg's matrix stack (matrix.h STACK_SIZE): 49 pushes on the first

struct Spec {
    const char* name;
    C command;
    std::uint32_t least;  // the numbers cpfg needs to draw it
    const char* expects;  // what they are
};

// cpfg's keywords (background.c, syn[]), with what DrawPrimitives reads of each.
constexpr Spec kSpecs[] = {
    {"polygon", C::Polygon, 9, "at least 3 points, x y z each"},
    {"polygonuv", C::PolygonUV, 18, "at least 3 points with their normals, x y z nx ny nz each"},
    {"rectangle", C::Rectangle, 2, "a width and a height (then x y, then a factor of its emission)"},
    {"mesh", C::Mesh, 12, "at least 2 rows of 2 points, x y z each"},
    {"prism", C::Prism, 3, "its sizes x y z"},
    {"box", C::Prism, 3, "its sizes x y z"},
    {"cone", C::Cone, 3, "a base radius, a top radius and a height"},
    {"cylinder", C::Cylinder, 2, "a radius and a height"},
    {"sphere", C::Sphere, 1, "a radius"},
    {"material", C::Material, 4, "4, 8, 12, 16 or 17 numbers (RGBA ambient, diffuse, specular, emission, then shininess)"},
    {"pushmatrix", C::PushMatrix, 0, "no numbers"},
    {"popmatrix", C::PopMatrix, 0, "no numbers"},
    {"translate", C::Translate, 3, "x y z"},
    {"rotate", C::Rotate, 4, "an angle in degrees and an axis x y z"},
    {"scale", C::Scale, 3, "x y z"},
    {"multmatrix", C::MultMatrix, 16, "16 numbers, the matrix row by row"},
};

const Spec* specOf(std::string_view word) {
    for (const Spec& s : kSpecs)
        if (word == s.name) return &s;
    return nullptr;
}

// How many of its `n` numbers a command uses (cpfg's DrawPrimitives): whole points of a
// polygon, whole rows of a mesh, whole colours of a material.
std::uint32_t used(const Spec& s, std::uint32_t n) {
    switch (s.command) {
        case C::Polygon: return n - n % 3;
        case C::PolygonUV:
        case C::Mesh: return n - n % 6;
        case C::Rectangle: return n >= 5 ? 5 : n >= 4 ? 4 : 2;
        case C::Material: return n >= 17 ? 17 : n - n % 4;
        default: return s.least;
    }
}

// A number as cpfg's fscanf("%f") reads a whole word: a sign, digits, a point, an exponent.
// Finite only (no inf, nan or hexadecimal: no editor writes them).
std::optional<float> number(std::string_view w) {
    if (!w.empty() && w[0] == '+') w.remove_prefix(1);
    if (w.empty() || w.size() > 64) return std::nullopt;
    for (char c : w)
        if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E')) return std::nullopt;
    float v = 0;
    const auto r = std::from_chars(w.data(), w.data() + w.size(), v, std::chars_format::general);
    if (r.ec != std::errc() || r.ptr != w.data() + w.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::string plural(std::uint32_t n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

}  // namespace

const std::vector<std::string>& backgroundCommands() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (const Spec& s : kSpecs) v.emplace_back(s.name);
        return v;
    }();
    return names;
}

bool BackgroundScene::ok() const {
    return std::none_of(problems.begin(), problems.end(), [](const Problem& p) { return p.diagnostic.severity == Severity::Error; });
}

void readBackgroundScene(std::string_view text, const std::string& file, BackgroundScene& scene, const IncludeReader& include) {
    if (scene.files.size() > 60000) {  // file numbers are 16 bits
        scene.problems.push_back({file, {0, 0, "too many background-scene files: not read"}});
        return;
    }
    const Preprocessed pre = preprocessWords(text, file, include);
    const size_t base = scene.files.size();
    scene.files.insert(scene.files.end(), pre.files.begin(), pre.files.end());
    auto report = [&](std::uint16_t f, int line, int col, std::string message, Severity s = Severity::Error) {
        if (scene.problems.size() < kMaxProblems) scene.problems.push_back({scene.files[base + f], {line, col, std::move(message), s}});
    };
    for (const auto& p : pre.problems)
        report(p.file, p.diagnostic.line, p.diagnostic.col, p.diagnostic.message, p.diagnostic.severity);
    const std::vector<PreprocessedWord>& w = pre.words;
    auto at = [&](const PreprocessedWord& x, std::string message, Severity s = Severity::Error) {
        report(x.file, x.line, x.col, std::move(message), s);
    };
    for (size_t i = 0; i < w.size();) {
        const PreprocessedWord& word = w[i];
        if (word.text[0] == '#') {  // what the preprocessor leaves on a line: cpfg skips the rest of it
            for (++i; i < w.size() && w[i].file == word.file && w[i].line == word.line;) ++i;
            continue;
        }
        const Spec* spec = specOf(word.text);
        if (!spec) {
            const std::string near = closestMatch(word.text, backgroundCommands());
            at(word, number(word.text) ? "expected a command (polygon, sphere, material ...) before the number '" + word.text + "'"
                                       : "unknown background-scene command '" + word.text + "'" +
                                             (near.empty() ? " (expected polygon, polygonuv, rectangle, mesh, prism, box, cone, "
                                                             "cylinder, sphere, material, pushmatrix, popmatrix, translate, "
                                                             "rotate, scale or multmatrix)"
                                                           : " (did you mean '" + near + "'?)") +
                                             "; skipped with its numbers, as cpfg skips it");
            for (++i; i < w.size() && number(w[i].text);) ++i;
            continue;
        }
        const size_t first = scene.values.size();
        size_t j = i + 1;
        for (; j < w.size(); ++j) {
            const std::optional<float> v = number(w[j].text);
            if (!v) break;
            if (scene.values.size() >= kMaxValues) {
                at(w[j], "more than a million numbers: the rest of the scene is not read");
                scene.values.resize(first);
                return;
            }
            scene.values.push_back(*v);
        }
        const std::uint32_t n = std::uint32_t(scene.values.size() - first);
        const std::string name = "'" + word.text + "'";
        if (n < spec->least) {
            if (j < w.size())
                at(w[j], name + " expects " + spec->expects + "; found " + (n ? plural(n, "number") + ", then " : "") + "'" + w[j].text + "'");
            else
                at(word, name + " expects " + spec->expects + "; the file ends after " + plural(n, "number"));
            scene.values.resize(first);
            i = j + (j < w.size() && !specOf(w[j].text) ? 1 : 0);  // a word named here is not named again
            continue;
        }
        const std::uint32_t u = used(*spec, n);
        if (u < n) {
            const std::uint32_t extra = n - u;
            const std::string these = extra == 1 ? (u ? "the next one is" : "this one is")
                                                 : (u ? "the next " : "these ") + std::to_string(extra) + " are";
            at(w[i + 1 + u],
               name + (u ? " uses " + plural(u, "number") + " (" + spec->expects + ")" : " takes no numbers") + "; " + these +
                   " ignored, as cpfg ignores them",
               Severity::Warning);
        }
        scene.values.resize(first + u);
        i = j;
        const float* v = scene.values.data() + first;
        if (spec->command == C::PushMatrix && scene.pushed + 1 >= kStackSize) {
            at(word, "cpfg's matrix stack holds 50 matrices: this 'pushmatrix' is ignored, as cpfg ignores it", Severity::Warning);
        } else if (spec->command == C::PopMatrix && scene.pushed == 0) {
            at(word, "'popmatrix' with no 'pushmatrix' before it: ignored, as cpfg ignores it", Severity::Warning);
        } else if (spec->command == C::Rotate && v[1] == 0 && v[2] == 0 && v[3] == 0) {
            at(word, "'rotate' about the axis 0 0 0, which has no direction: skipped", Severity::Warning);
        } else {
            scene.pushed += spec->command == C::PushMatrix ? 1 : spec->command == C::PopMatrix ? -1 : 0;
            scene.items.push_back({spec->command, std::uint32_t(first), u, std::uint16_t(base + word.file), word.line});
            continue;
        }
        scene.values.resize(first);
    }
}

void loadBackgroundScene(const std::filesystem::path& path, BackgroundScene& scene) {
    errno = 0;
    const std::optional<std::string> text = readFile(path);
    if (!text) {
        const int err = errno;
        scene.files.push_back(path.string());
        scene.problems.push_back({path.string(), {0, 0, std::string("cannot be read: ") + (err ? std::strerror(err) : "unknown error")}});
        return;
    }
    const IncludeReader beside = [](const std::string& from, const std::string& name, std::string& found, std::string& error) {
        const std::filesystem::path p = std::filesystem::path(from).parent_path() / name;
        errno = 0;
        std::optional<std::string> t = readFile(p);
        if (!t) error = errno ? std::strerror(errno) : "it cannot be read";
        found = p.lexically_normal().string();
        return t;
    };
    readBackgroundScene(*text, path.string(), scene, beside);
}

}  // namespace sprout::vlab
