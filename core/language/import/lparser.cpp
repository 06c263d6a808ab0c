// Lparser 5 files -> .lsys. Lparser's commands differ from ABOP's; each is mapped to what
// Sprout's turtle does the same way (see the table in translate()).
#include <cmath>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <set>
#include <sstream>

#include "core/language/import/import.hpp"

namespace sprout {
namespace {

// A recursion depth from any number: out-of-range values stay out of range (the .lsys
// parser then says what n may be) without undefined conversions.
int countOf(double v) { return std::isnan(v) ? -1 : int(std::clamp(v, -1.0, 1e6)); }


// Lparser's 16-colour table is not documented; this one keeps the roles its examples give
// the indices: c(12) "close to that of the stem" (seed document 001), c(4) and c(8) leaves,
// the indices around them greens (colour steps with c walk through them), 13-15 flowers.
const char* kLparserPalette =
    "#5a3d22 #3f6b25 #4e8f2e #5e9e34 #4f8a2c #6aa83a #7a5a30 #8fbf4a "
    "#5d9a3a #79b544 #8fd16a #a6cb66 #7a5230 #e08fd0 #f0d040 #f5f5f0";

std::string trimmed(std::string_view s) {
    size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return std::string(s.substr(a, b - a));
}

struct Translator {
    double angle = 45;
    std::set<std::string> renamed;  // symbols renamed because Sprout's turtle would act on them
    std::vector<Diagnostic>* diags = nullptr;
    int line = 0;

    // Symbols that draw or turn in Sprout but are plain symbols in Lparser.
    static bool clashes(char c) { return c == 'G' || c == '/' || c == '\\' || c == ',' || c == '=' || c == '*'; }

    std::string name(char c) {
        if (!clashes(c)) return std::string(1, c);
        std::string n = std::string("Lp") + (c == '/' ? "slash" : c == '\\' ? "backslash" : c == ',' ? "comma"
                                                          : c == '=' ? "equals" : c == '*' ? "star" : std::string(1, c));
        renamed.insert(n);
        return n;
    }

    std::string translate(std::string_view s) {
        std::string out;
        for (size_t i = 0; i < s.size(); ++i) {
            char c = s[i];
            if (std::isspace(static_cast<unsigned char>(c))) continue;
            std::string param;
            // Text copied from documents sometimes lost the '(' of a parameter: `".7)` for
            // `"(.7)`. A number closed by ')' right after a command is read as its parameter.
            if (i + 1 < s.size() && s[i + 1] != '(' && c != '\0' && std::strchr("\"';:?!~t+-&^<>c", c)) {
                size_t j = i + 1;
                while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.' || s[j] == '-')) ++j;
                if (j > i + 1 && j < s.size() && s[j] == ')') {
                    param = std::string(s.substr(i + 1, j - i - 1));
                    i = j;
                }
            }
            if (param.empty() && i + 1 < s.size() && s[i + 1] == '(') {
                size_t close = s.find(')', i + 2);
                if (close == std::string_view::npos) {
                    diags->push_back({line, int(i + 1), "this '(' is never closed", Severity::Error});
                    return out;
                }
                param = trimmed(s.substr(i + 2, close - i - 2));
                i = close;
            }
            auto with = [&](const char* cmd, const char* fallback) {
                return std::string(cmd) + "(" + (param.empty() ? std::string(fallback) : param) + ")";
            };
            auto plain = [&](const std::string& cmd) { return param.empty() ? cmd : cmd + "(" + param + ")"; };
            switch (c) {
                case 'F': case 'f': case 'g': case '+': case '-': case '&': case '^':
                    out += plain(std::string(1, c));
                    break;
                case 'Z': out += param.empty() ? "@L(0.5)F@L(2)" : "F((" + param + ")/2)"; break;  // half step
                case 'z': out += param.empty() ? "@L(0.5)f@L(2)" : "f((" + param + ")/2)"; break;
                // Lparser's roll turns the other way round from cpfg's: with '>' as cpfg's '\'
                // the seed documents' "&(-90)>(90)-(90)" leaves the turtle facing up, as they
                // say it does, and files without it grow upwards too.
                case '<': out += plain("/"); break;
                case '>': out += plain("\\"); break;
                case '%': out += "/(180)"; break;
                case '|': out += "|"; break;
                case '$': out += "$"; break;
                case '~': {  // a random turn, pitch and roll, each up to the angle
                    std::string x = param.empty() ? std::to_string(angle) : param;
                    out += "+(rand(-(" + x + "),(" + x + ")))&(rand(-(" + x + "),(" + x + ")))/(rand(-(" + x + "),(" + x + ")))";
                    break;
                }
                case 't': out += with("@T", "0.2"); break;   // gravity
                case '"': out += with("@L", "1.1"); break;   // longer
                case '\'': out += with("@L", "0.9"); break;  // shorter
                case ';': out += with("@A", "1.1"); break;   // wider angle
                case ':': out += with("@A", "0.9"); break;   // narrower angle
                case '?': out += with("@W", "1.4"); break;   // thicker
                case '!': out += with("@W", "0.7"); break;   // thinner
                case 'c': out += param.empty() ? ";" : ";(" + param + ")"; break;  // colour
                case '_': break;                                                   // identity
                case '[': case ']': case '{': case '}': case '.': out += c; break;
                case '@': break;  // end marker of the positional format
                default:
                    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) {
                        diags->push_back({line, int(i + 1), std::string("unexpected character in an Lparser string"), Severity::Error});
                        return out;
                    }
                    out += plain(name(c));
            }
        }
        return out;
    }
};

struct LparserRule {
    char pred;
    std::string succ;
    int line;
};

// What an Lparser file says, in either of its formats.
struct LparserFile {
    int recursion = 4;
    double thickness = 10;
    std::string axiom;
    int axiomLine = 0;
    std::vector<LparserRule> rules;
    std::vector<std::string> palette;
    int lines = 0;  // lines read (the last one, where a missing axiom is reported)
};

// Reads the file line by line: keywords (`recursion 4`, `rule X = ...`), or the older format
// of values by position. The angle goes to the translator, which turns by it.
LparserFile readLparserFile(std::string_view source, Translator& tr, std::vector<Diagnostic>& diags) {
    LparserFile f;
    std::istringstream in{std::string(source)};
    std::string raw;
    int number = 0;
    int positional = 0;  // the older format: values by position
    bool lastWasString = false, lastWasAxiom = false;
    while (std::getline(in, raw)) {
        ++number;
        tr.line = number;
        std::string line = raw;
        if (size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        line = trimmed(line);
        if (line.empty()) continue;
        std::istringstream words(line);
        std::string key;
        words >> key;
        std::string rest = trimmed(std::string_view(line).substr(key.size()));
        auto number_ = [&](double& out) {
            if (std::sscanf(rest.c_str(), "%lf", &out) != 1)
                diags.push_back({number, int(key.size() + 2), "'" + key + "' needs a number", Severity::Error});
        };
        if (positional == 0 && (std::isdigit(static_cast<unsigned char>(key[0])) || key[0] == '.')) positional = 1;
        if (positional) {  // recursion, angle, thickness, axiom, rules X=..., @
            if (key == "@") break;
            if (positional <= 3) {
                double v = std::atof(key.c_str());
                if (positional == 1) f.recursion = countOf(v);
                else if (positional == 2) tr.angle = v;
                else f.thickness = v;
                ++positional;
                continue;
            }
            if (positional == 4) {
                f.axiom = line;
                f.axiomLine = number;
                ++positional;
                continue;
            }
            size_t eq = line.find('=');
            if (eq == 1) f.rules.push_back({line[0], line.substr(2), number});
            else diags.push_back({number, 1, "expected a rule such as 'X=F[+X]'", Severity::Error});
            continue;
        }
        double v = 0;
        // A line that starts indented and is not a keyword continues the previous axiom or
        // rule (listings in documents wrap long rules).
        const bool indented = !raw.empty() && (raw[0] == ' ' || raw[0] == '\t');
        static const std::set<std::string> keywords = {"recursion", "angle", "thickness", "min_thickness", "shape",
                                                       "switch_yz", "switch_zy", "no_wait", "bounding_box", "seed",
                                                       "color", "axiom", "rule"};
        if (indented && !keywords.count(key) && lastWasString) {
            if (f.rules.empty() || lastWasAxiom) f.axiom += line;
            else f.rules.back().succ += line;
            continue;
        }
        lastWasString = key == "axiom" || key == "rule";
        lastWasAxiom = key == "axiom";
        if (key == "recursion") {
            number_(v);
            f.recursion = countOf(v);
        } else if (key == "angle") {
            number_(tr.angle);
        } else if (key == "thickness") {
            number_(f.thickness);
        } else if (key == "min_thickness" || key == "shape" || key == "switch_yz" || key == "switch_zy" ||
                   key == "no_wait" || key == "bounding_box" || key == "seed") {
            // Output and viewer settings of Lparser: nothing to translate.
        } else if (key == "color") {
            // Read by a stream, not sscanf's %d (undefined past int's range): an overflow fails.
            int i = 0, red = 0, green = 0, blue = 0;
            std::istringstream numbers(rest);
            if (!(numbers >> i >> red >> green >> blue) || i < 0 || i > 126) {
                diags.push_back({number, 7, "expected 'color INDEX RED GREEN BLUE'", Severity::Error});
                continue;
            }
            if (f.palette.empty()) {
                std::istringstream p(kLparserPalette);
                for (std::string c; p >> c;) f.palette.push_back(c);
            }
            if (f.palette.size() <= size_t(i)) f.palette.resize(size_t(i) + 1, "#808080");
            char hex[8];
            std::snprintf(hex, sizeof hex, "#%02x%02x%02x", red & 255, green & 255, blue & 255);
            f.palette[size_t(i)] = hex;
        } else if (key == "axiom") {
            f.axiom = rest;
            f.axiomLine = number;
        } else if (key == "rule") {
            size_t eq = rest.find('=');
            std::string pred = trimmed(std::string_view(rest).substr(0, eq == std::string::npos ? 0 : eq));
            if (eq == std::string::npos || pred.size() != 1) {
                diags.push_back({number, 6, "expected 'rule X = successor' with a one-character X", Severity::Error});
                continue;
            }
            f.rules.push_back({pred[0], trimmed(std::string_view(rest).substr(eq + 1)), number});
        } else {
            diags.push_back({number, 1, "unknown Lparser keyword '" + key + "' (ignored)", Severity::Warning});
        }
    }
    f.lines = number;
    return f;
}

// Lparser closes what a string leaves open; listings copied from documents drop a ']'
// now and then. Balance each string, with a warning.
std::string balanced(std::string text, int line, std::vector<Diagnostic>& diags) {
    int depth = 0;
    std::string out;
    for (char c : text) {
        if (c == ']' && depth == 0) {
            diags.push_back({line, 1, "a ']' closes no branch (dropped)", Severity::Warning});
            continue;
        }
        depth += (c == '[') - (c == ']');
        out += c;
    }
    if (depth > 0) {
        diags.push_back({line, 1, std::to_string(depth) + " unclosed '[' (closed at the end)", Severity::Warning});
        out.append(size_t(depth), ']');
    }
    return out;
}

}  // namespace

ImportResult importLparser(std::string_view source, std::string_view name) {
    ImportResult r;
    Translator tr;
    tr.diags = &r.diagnostics;
    const LparserFile f = readLparserFile(source, tr, r.diagnostics);
    if (f.axiom.empty()) r.diagnostics.push_back({std::max(f.lines, 1), 1, "the file has no axiom", Severity::Error});

    std::ostringstream out;
    out << "# Imported from Lparser: " << name << "\n";
    out << "n: " << f.recursion << "\nangle: " << tr.angle << "\n";
    // Lparser's thickness is a percentage of the segment length.
    out << "width: " << f.thickness / 100.0 << "\n";
    out << "palette: " << (f.palette.empty() ? kLparserPalette : [&] {
        std::string p;
        for (const auto& c : f.palette) p += (p.empty() ? "" : " ") + c;
        return p;
    }()) << "\nseed: 1\n";
    tr.line = f.axiomLine;
    std::string ax = balanced(tr.translate(f.axiom), f.axiomLine, r.diagnostics);
    std::vector<std::string> lines;
    for (const LparserRule& rule : f.rules) {
        tr.line = rule.line;
        std::string pred = tr.name(rule.pred);
        if (rule.pred == '(' || rule.pred == ')' || rule.pred == '[' || rule.pred == ']') {
            r.diagnostics.push_back({rule.line, 6, "a rule cannot rewrite a bracket", Severity::Error});
            continue;
        }
        lines.push_back(pred + " -> " + balanced(tr.translate(rule.succ), rule.line, r.diagnostics));
    }
    if (!tr.renamed.empty()) {
        out << "module:";
        for (const auto& n : tr.renamed) out << " " << n;
        out << "\n";
    }
    out << "axiom: " << ax << "\n";
    for (const auto& l : lines) out << l << "\n";
    r.text = out.str();
    return r;
}

}  // namespace sprout
