#include "core/language/file_kind.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <string>


namespace sprout {

bool isForestScene(std::string_view text) {
    std::istringstream in{std::string(text.substr(0, 4096))};
    std::string line;
    while (std::getline(in, line)) {
        size_t a = line.find_first_not_of(" \t");
        if (a == std::string::npos || line[a] == '#') continue;
        return line.compare(a, 6, "scene:") == 0 && line.find("forest") != std::string::npos;
    }
    return false;
}

namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return out;
}

bool hasExtension(std::string_view path, std::string_view ext) {
    return path.size() >= ext.size() && lower(path.substr(path.size() - ext.size())) == ext;
}

std::string_view trimView(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// Calls `f` on each line (trimmed) of the first 64 KiB: enough to decide, bounded on huge files.
template <class F>
void eachLine(std::string_view text, F&& f) {
    text = text.substr(0, 1 << 16);
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        if (!f(trimView(text.substr(start, end - start)))) return;
        start = end + 1;
    }
}

// `key` followed by optional spaces and ':' (case-insensitive), as cpfg writes its settings.
bool isKey(std::string_view line, std::string_view key) {
    if (line.size() < key.size() || lower(line.substr(0, key.size())) != key) return false;
    std::string_view rest = trimView(line.substr(key.size()));
    return rest.starts_with(":");
}

// Fractint: `Name {` opening a system, with `;` comments.
bool looksLikeFractint(std::string_view text) {
    bool found = false;
    eachLine(text, [&](std::string_view l) {
        if (l.empty() || l.starts_with(";")) return true;
        size_t brace = l.find('{');
        if (brace != std::string_view::npos && brace > 0 && l.find("->") == std::string_view::npos &&
            l.find(':') == std::string_view::npos) {
            std::string_view name = trimView(l.substr(0, brace));
            found = !name.empty() && name.find(' ') == std::string_view::npos;
        }
        return false;
    });
    return found;
}

// Lparser: the keyword format starts with `recursion N`; the positional one with a number.
bool looksLikeLparser(std::string_view text) {
    bool found = false;
    eachLine(text, [&](std::string_view l) {
        if (l.empty() || l.starts_with("#")) return true;
        std::string w = lower(l.substr(0, l.find_first_of(" \t")));
        // "angle = 90", "angle: 90": the settings of the .lsys family, not Lparser's "angle 90".
        if (l.find('=') != std::string_view::npos || l.find(':') != std::string_view::npos) return false;
        found = w == "recursion" || w == "angle" || w == "thickness" || w == "color" || w == "min_thickness" ||
                w == "shape" || w == "switch_yz" ||
                (!w.empty() && std::all_of(w.begin(), w.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.'; }));
        return false;
    });
    return found;
}

}  // namespace

// `#define RAND (random()-0.5)`: a text macro with a call in it (cpfg's, put in place where
// its name is used), not a constant of the .lsys family (`#define r1 0.9`).
static bool textMacro(std::string_view l) {
    if (!l.starts_with("#define")) return false;
    size_t i = 7;
    while (i < l.size() && (l[i] == ' ' || l[i] == '\t')) ++i;
    while (i < l.size() && (std::isalnum(static_cast<unsigned char>(l[i])) || l[i] == '_')) ++i;  // the name
    for (size_t k = i; k + 1 < l.size(); ++k)
        if (std::isalpha(static_cast<unsigned char>(l[k])) && l[k + 1] == '(') return true;
    return false;
}

bool looksLikeCpfg(std::string_view text) {
    bool found = false;
    // ABOP's printed notation ("ω:", "δ = 25.7°", "→") names cpfg's `derivation length:` too:
    // it is read by the .lsys parser.
    bool notation = false;
    eachLine(text, [&](std::string_view l) {
        notation |= l.starts_with("\xCF\x89") || l.starts_with("\xCE\xB4") || l.find("\xE2\x86\x92") != std::string_view::npos;
        return !notation;
    });
    if (notation) return false;
    eachLine(text, [&](std::string_view l) {
        std::string low = lower(l.substr(0, 24));
        if (isKey(l, "lsystem") || isKey(l, "derivation length") || isKey(l, "maximum depth") ||
            isKey(l, "consider") || low == "endlsystem" || low.starts_with("endlsystem ") ||
            low == "decomposition" || low == "decomposition:" || low == "homomorphism" ||
            low.starts_with("/*") || low.starts_with("#include") || low.starts_with("produce ") ||
            low.starts_with("nproduce ") || textMacro(l)) {
            found = true;
            return false;
        }
        return true;
    });
    return found;
}

bool looksLikeLpy(std::string_view text) {
    bool axiom = false, lpy = false, cpfg = false;
    eachLine(text, [&](std::string_view l) {
        if (l.starts_with("Axiom:") || l.starts_with("Axiom :") || l.starts_with("axiom:")) axiom = true;
        if (isKey(l, "lsystem") || l.starts_with("/*")) cpfg = true;
        if (isKey(l, "production") || l.starts_with("def ") || l.starts_with("import ") || l.starts_with("from ") ||
            l.starts_with("nproduce ") || l.find("__initialiseContext__") != std::string_view::npos ||
            l.find("###### INITIALISATION ######") != std::string_view::npos)
            lpy = true;
        return true;
    });
    return axiom && lpy && !cpfg;
}

bool looksLikeIfs(std::string_view text) {
    bool result = false;
    eachLine(text, [&](std::string_view l) {
        std::string line(l.substr(0, l.find('#')));
        if (line.find_first_not_of(" \t\r") == std::string::npos) return true;
        if (line.find("->") != std::string::npos) return false;
        std::istringstream words(line);
        double v;
        int n = 0;
        while (words >> v) ++n;
        result = n == 7 && words.eof();
        return false;
    });
    return result;
}

FileKind detectFileKind(std::string_view path, std::string_view bytes) {
    if (bytes.starts_with("\x89PNG\r\n\x1a\n")) return FileKind::Png;
    if (hasExtension(path, ".png")) return FileKind::Png;  // damaged: the PNG reader says how
    if (isForestScene(bytes)) return FileKind::Forest;
    if (looksLikeIfs(bytes)) return FileKind::Ifs;
    if (hasExtension(path, ".lpy") || looksLikeLpy(bytes)) return FileKind::Lpy;
    if (looksLikeCpfg(bytes)) return FileKind::Cpfg;
    // The extension decides between tools that share it only when the content does not.
    if (hasExtension(path, ".lsys")) return FileKind::Lsys;
    // `.ls` is Lparser's and L-system Explorer's (the web's cpfg family): Lparser's files are
    // lines of numbers and its keywords; the others are read as their content says.
    if (hasExtension(path, ".ls")) return looksLikeLparser(bytes) ? FileKind::Lparser : FileKind::Lsys;
    if (hasExtension(path, ".l")) return looksLikeFractint(bytes) || bytes.find("-->") == std::string_view::npos ? FileKind::Fractint : FileKind::Cpfg;
    if (hasExtension(path, ".ifs")) return FileKind::Ifs;
    if (hasExtension(path, ".forest")) return FileKind::Forest;
    if (looksLikeFractint(bytes)) return FileKind::Fractint;
    if (!path.empty() && looksLikeLparser(bytes) && bytes.find("->") == std::string_view::npos) return FileKind::Lparser;
    return FileKind::Lsys;
}

ParseOptions parseOptionsFor(FileKind kind, const std::string& path) {
    ParseOptions o;
    o.cpfg = cpfgFamily(kind);
    o.explorer = (kind == FileKind::Lsys || kind == FileKind::Cpfg) && hasExtension(path, ".ls");
    o.tabContinues = kind == FileKind::Cpfg && !o.explorer;
    if (!path.empty()) {  // #include (cpfg) and files an environment names read beside the grammar
        const size_t slash = path.find_last_of('/');
        o.include = includeFromFolder(slash == std::string::npos ? "." : path.substr(0, slash));
        o.fileName = slash == std::string::npos ? path : path.substr(slash + 1);
        o.folder = slash == std::string::npos ? "." : path.substr(0, slash);
    }
    return o;
}

ParseResult parseDetected(std::string_view text, const std::string& path) {
    const FileKind kind = detectFileKind(path, text);
    ParseOptions o = parseOptionsFor(cpfgFamily(kind) ? kind : FileKind::Lsys, path);
    o.explorer = o.explorer && kind != FileKind::Lparser;
    return parse(text, o);
}

const char* fileKindName(FileKind kind) {
    switch (kind) {
        case FileKind::Lsys: return ".lsys grammar";
        case FileKind::Cpfg: return "cpfg L-system";
        case FileKind::Lpy: return "L-Py model";
        case FileKind::Lparser: return "Lparser file";
        case FileKind::Fractint: return "Fractint L-system file";
        case FileKind::Ifs: return "iterated function system";
        case FileKind::Forest: return "forest scene";
        case FileKind::Png: return "PNG picture";
    }
    return "file";
}

}  // namespace sprout
