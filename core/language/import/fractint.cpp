// Fractint .l files -> .lsys. Fractint's conventions (Fractint 19.6 help): symbols are
// case-insensitive; `Angle n` means 360/n degrees; F and D draw, G and M move; \nn and /nn
// turn left and right by nn degrees; `!` swaps the meaning of the turns; `|` turns around;
// @nn multiplies the step by nn (@Inn by 1/nn, @Qnn by its square root); <nn >nn change the
// colour, Cnn sets it; `;` starts a comment; several rules for one letter are joined.
#include <cctype>
#include <map>
#include <sstream>

#include "core/language/import/import.hpp"

namespace sprout {
namespace {

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

struct Block {
    std::string name;
    int line = 0;
    std::vector<std::pair<int, std::string>> lines;  // line number, text without the comment
};

std::vector<Block> blocks(std::string_view source) {
    std::vector<Block> out;
    std::istringstream in{std::string(source)};
    std::string raw;
    int number = 0;
    Block* open = nullptr;
    while (std::getline(in, raw)) {
        ++number;
        std::string line = raw.substr(0, raw.find(';'));
        if (!open) {
            size_t brace = line.find('{');
            if (brace == std::string::npos) continue;
            std::string name = line.substr(0, brace);
            while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
            while (!name.empty() && std::isspace(static_cast<unsigned char>(name.front()))) name.erase(0, 1);
            out.push_back({name, number, {}});
            open = &out.back();
            line = line.substr(brace + 1);
        }
        size_t close = line.find('}');
        open->lines.emplace_back(number, line.substr(0, close));
        if (close != std::string::npos) open = nullptr;
    }
    return out;
}

// Reads a number after a command (digits, '.', a leading '-').
std::string numberAt(const std::string& s, size_t& i) {
    size_t start = i;
    if (i < s.size() && s[i] == '-') ++i;
    while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) ++i;
    return s.substr(start, i - start);
}

std::string translate(const std::string& s, int line, std::vector<Diagnostic>& diags) {
    std::string out;
    for (size_t i = 0; i < s.size();) {
        char c = char(std::toupper(static_cast<unsigned char>(s[i])));
        ++i;
        if (std::isspace(static_cast<unsigned char>(c))) continue;
        switch (c) {
            case 'F': case 'D': out += 'F'; break;
            case 'G': case 'M': out += 'f'; break;
            case '+': case '-': case '[': case ']': case '|': out += c; break;
            case '!': out += "@A(-1)"; break;  // swap the turns
            case '\\': case '/': {
                std::string n = numberAt(s, i);
                if (n.empty()) {
                    diags.push_back({line, int(i), std::string("'") + c + "' needs a number of degrees", Severity::Error});
                    return out;
                }
                out += (c == '\\' ? "+(" : "-(") + n + ")";
                break;
            }
            case '@': {
                bool inverse = false, root = false;
                while (i < s.size() && (std::toupper(static_cast<unsigned char>(s[i])) == 'I' ||
                                        std::toupper(static_cast<unsigned char>(s[i])) == 'Q')) {
                    (std::toupper(static_cast<unsigned char>(s[i])) == 'I' ? inverse : root) = true;
                    ++i;
                }
                std::string n = numberAt(s, i);
                if (n.empty()) {
                    diags.push_back({line, int(i), "'@' needs a number", Severity::Error});
                    return out;
                }
                std::string v = root ? "sqrt(" + n + ")" : n;
                out += "@L(" + (inverse ? "1/" + v : v) + ")";
                break;
            }
            case '<': case '>': {
                std::string n = numberAt(s, i);
                int k = n.empty() ? 1 : n.size() > 3 ? 64 : std::max(0, std::min(64, std::atoi(n.c_str())));
                for (int j = 0; j < k; ++j) out += c == '<' ? ';' : ',';
                break;
            }
            case 'C': {
                std::string n = numberAt(s, i);
                out += n.empty() ? ";" : ";(" + n + ")";
                break;
            }
            default:
                // A letter is a plain symbol; Fractint ignores anything else (stray quotes,
                // commas and numbers are common in the collection).
                if (std::isalpha(static_cast<unsigned char>(c))) out += c;
        }
    }
    return out;
}

}  // namespace

std::vector<FractintSystem> listFractint(std::string_view source) {
    std::vector<FractintSystem> out;
    for (const auto& b : blocks(source)) out.push_back({b.name, b.line});
    return out;
}

ImportResult importFractint(std::string_view source, std::string_view system) {
    ImportResult r;
    auto all = blocks(source);
    const Block* b = nullptr;
    for (const auto& x : all)
        if (system.empty() || lower(x.name) == lower(std::string(system))) {
            b = &x;
            break;
        }
    if (!b) {
        r.diagnostics.push_back({1, 1, all.empty() ? "no 'Name { ... }' system in the file"
                                                   : "no system named '" + std::string(system) + "' in the file",
                                 Severity::Error});
        return r;
    }
    double angle = 90;
    std::string axiom;
    std::map<char, std::string> rules;
    std::vector<char> order;
    for (const auto& [line, raw] : b->lines) {
        // `Angle 6`, `angle=6;` and `axiom=FX` are all written in the collection.
        std::string text = raw;
        {
            std::string l = lower(text);
            size_t at = l.find_first_not_of(" \t");
            for (const char* word : {"angle", "axiom"})
                if (at != std::string::npos && l.compare(at, 5, word) == 0 && at + 5 < l.size() && l[at + 5] == '=')
                    text[at + 5] = ' ';
        }
        std::istringstream words(text);
        std::string key;
        words >> key;
        if (key.empty()) continue;
        std::string k = lower(key);
        std::string rest = text.substr(text.find(key) + key.size());
        if (k == "angle") {
            int n = 0;
            words >> n;
            if (n <= 0) {
                r.diagnostics.push_back({line, 1, "'Angle' needs a positive whole number (360/n degrees)", Severity::Error});
                continue;
            }
            angle = 360.0 / n;
        } else if (k == "axiom") {
            axiom = translate(rest, line, r.diagnostics);
        } else if (size_t eq = text.find('='); eq != std::string::npos) {
            std::string pred;
            for (char c : text.substr(0, eq))
                if (!std::isspace(static_cast<unsigned char>(c))) pred += char(std::toupper(static_cast<unsigned char>(c)));
            if (pred.size() != 1) {
                r.diagnostics.push_back({line, 1, "a Fractint rule rewrites one letter: 'X=...'", Severity::Error});
                continue;
            }
            char p = pred[0] == 'D' ? 'F' : pred[0] == 'G' || pred[0] == 'M' ? 'f' : pred[0];
            if (!rules.count(p)) order.push_back(p);
            rules[p] += translate(text.substr(eq + 1), line, r.diagnostics);
        } else {
            r.diagnostics.push_back({line, 1, "expected 'Angle n', 'Axiom ...' or a rule 'X=...'", Severity::Error});
        }
    }
    if (axiom.empty()) r.diagnostics.push_back({b->line, 1, "'" + b->name + "' has no axiom", Severity::Error});
    std::ostringstream out;
    out << "# Imported from Fractint: " << b->name << "\nn: 4\nangle: " << angle << "\nview: 2d\naxiom: " << axiom << "\n";
    for (char p : order) out << p << " -> " << rules[p] << "\n";
    r.text = out.str();
    return r;
}

ImportResult importFile(std::string_view path, std::string_view source, std::string_view system) {
    size_t slash = path.find_last_of('/');
    std::string_view name = slash == std::string_view::npos ? path : path.substr(slash + 1);
    const FileKind kind = detectFileKind(path, source);
    ImportResult r;
    switch (kind) {
        case FileKind::Lparser: r = importLparser(source, name); break;
        case FileKind::Fractint: r = importFractint(source, system); break;
        case FileKind::Png: return importPng(source);
        default:
            r.text = std::string(source);
            r.kind = kind;
            break;
    }
    r.source = kind;
    return r;
}

}  // namespace sprout
