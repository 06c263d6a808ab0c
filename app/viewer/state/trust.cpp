#include "app/viewer/state/trust.hpp"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/base/atomic_file.hpp"
#include "core/base/read_file.hpp"
#include "core/base/sha256.hpp"

namespace sprout::viewer {
namespace fs = std::filesystem;
namespace {

fs::path defaultTrustFile() {
    fs::path dir;
    if (const char* c = std::getenv("XDG_CONFIG_HOME"); c && *c) dir = fs::path(c) / "sprout";
    else if (const char* h = std::getenv("HOME"); h && *h) dir = fs::path(h) / ".config" / "sprout";
    else dir = fs::temp_directory_path() / "sprout-config";
    return dir / "trusted-models";
}

bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// The names after `import` in `import a, b.c as d`.
void namesOf(std::string_view list, int line, std::vector<PythonImport>& out) {
    while (!list.empty()) {
        size_t comma = list.find(',');
        std::string_view item = trim(list.substr(0, comma));
        size_t end = 0;
        while (end < item.size() && identChar(item[end])) ++end;
        if (end > 0) out.push_back({line, std::string(item.substr(0, end))});
        if (comma == std::string_view::npos) break;
        list.remove_prefix(comma + 1);
    }
}

}  // namespace

std::vector<PythonImport> pythonImports(std::string_view text) {
    std::vector<PythonImport> out;
    int line = 0;
    while (!text.empty()) {
        ++line;
        size_t nl = text.find('\n');
        std::string_view l = trim(text.substr(0, nl));
        text = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
        if (size_t hash = l.find('#'); hash != std::string_view::npos) l = trim(l.substr(0, hash));
        if (l.rfind("import ", 0) == 0) {
            namesOf(l.substr(7), line, out);
        } else if (l.rfind("from ", 0) == 0) {
            std::string_view rest = trim(l.substr(5));
            size_t end = 0;
            while (end < rest.size() && identChar(rest[end])) ++end;
            if (end > 0 && trim(rest.substr(end)).rfind("import", 0) == 0) out.push_back({line, std::string(rest.substr(0, end))});
        }
    }
    return out;
}

TrustStore::TrustStore(fs::path file) : m_file(file.empty() ? defaultTrustFile() : std::move(file)) {}

TrustAnswer TrustStore::answer(std::string_view text) const {
    std::optional<std::string> file = readFile(m_file);
    if (!file) return TrustAnswer::None;
    std::istringstream in(*file);
    const std::string hash = sha256Hex(text);
    TrustAnswer found = TrustAnswer::None;
    std::string h, word;
    while (in >> h) {
        if (h.size() != 64) {  // a comment line
            std::getline(in, word);
            continue;
        }
        in >> word;
        if (h == hash) found = word == "trusted" ? TrustAnswer::Trusted : TrustAnswer::Refused;  // the last answer counts
    }
    return found;
}

bool TrustStore::remember(std::string_view text, TrustAnswer answer, std::string& error) {
    const std::string hash = sha256Hex(text);
    std::string kept = "# Sprout: L-Py models whose Python the user allowed or refused to run, by the SHA-256 of their text\n";
    if (std::optional<std::string> file = readFile(m_file)) {
        std::istringstream in(*file);
        std::string line;
        while (std::getline(in, line))
            if (line.size() > 65 && line[64] == ' ' && line.compare(0, 64, hash) != 0) kept += line + "\n";
    }
    if (answer != TrustAnswer::None) kept += hash + (answer == TrustAnswer::Trusted ? " trusted\n" : " refused\n");
    std::error_code ec;
    fs::create_directories(m_file.parent_path(), ec);
    return writeFileAtomically(m_file.string(), kept, error);
}

}  // namespace sprout::viewer
