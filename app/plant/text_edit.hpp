#pragma once
// Slider <-> text round trip: a slider writes its value back into the grammar text, so the
// text stays the single source of truth (and what is saved is what is shown).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sprout {

// Sets `key: value` in `text`: replaces the value of the first line with that key (keeping
// any jitter `~ sigma`), or inserts the line before the axiom when there is none.
std::string setDirective(std::string_view text, std::string_view key, std::string_view value);

// Sets the value of `define: name = value` / `#define name value`.
std::string setDefine(std::string_view text, std::string_view name, std::string_view value);

// The value text of the first `key:` line, if any.
std::optional<std::string> directiveValue(std::string_view text, std::string_view key);

// A number of an `environment:` line that the panel's sliders move (open L-systems): where it
// is in the text, what it means, and its value. Numbers written as expressions of defines have
// none: their defines' sliders move them.
struct EnvironmentNumber {
    enum class Kind { Position, Size, Count, Shadow, Azimuth, Elevation };
    int line = 0;                 // 1-based
    size_t begin = 0, end = 0;    // the number's bytes in the text
    std::string label;            // "sphere radius", "obstacle box x1", "light sun azimuth"
    Kind kind = Kind::Position;
    double value = 0;
    int sun = -1;                 // a light with no sun yet: 0 azimuth, 1 elevation (added when moved)
};
std::vector<EnvironmentNumber> environmentNumbers(std::string_view text);
// The text with that number set to `v` (for a light with no sun: " sun AZIMUTH ELEVATION" added).
std::string setEnvironmentNumber(std::string_view text, const EnvironmentNumber& number, double v);

// An L-Py model's scalar parameter (its INITIALISATION part: `scalars = [('NAME', 'Integer',
// 3, 1, 20), ('K', 'Float', 0.5, 0, 1, 2), ('ON', 'Bool', True)]`, or L-Py's older form
// without the type, `('NAME', 3, 1, 20)`): one slider or checkbox each, written back there.
struct LpyScalar {
    // Category: a heading of L-Py Studio's (`('Shape', 'Category')`, before 1.1 `('Shape', None)`):
    // no value; the scalars after it, up to the next, are its own.
    enum class Kind { Integer, Float, Bool, Category };
    std::string name;
    Kind kind = Kind::Float;
    double value = 0, min = 0, max = 1;
    size_t begin = 0, end = 0;  // the value's bytes in the text (a Category: none)
};
std::vector<LpyScalar> lpyScalars(std::string_view text);
std::string setLpyScalar(std::string_view text, const LpyScalar& scalar, double v);

// Whether `s` starts with `prefix`, letters compared without case.
bool startsWithNoCase(std::string_view s, std::string_view prefix);

// Shortest text for a slider value (3 significant decimals is what a slider can set).
std::string formatValue(double v);

}  // namespace sprout
