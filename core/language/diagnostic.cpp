#include "core/language/diagnostic.hpp"

#include <algorithm>

namespace sprout {

std::string formatDiagnostic(const Diagnostic& d, const std::string& file) {
    std::string out = file;
    if (d.line > 0) out += ":" + std::to_string(d.line) + ":" + std::to_string(d.col);
    out += d.severity == Severity::Warning ? ": warning: " : ": ";
    out += d.message;
    return out;
}

bool hasErrors(const std::vector<Diagnostic>& diags) {
    return std::any_of(diags.begin(), diags.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

// Optimal string alignment distance: Levenshtein plus adjacent transpositions, the most
// common typing slip ("anlge").
static size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        for (size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[a.size()][b.size()];
}

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    size_t bestDist = std::string::npos;
    for (const auto& c : candidates) {
        size_t d = editDistance(word, c);
        if (d < bestDist) {
            bestDist = d;
            best = c;
        }
    }
    // A suggestion must be closer than a rewrite: at most a third of the word may change.
    size_t limit = std::max<size_t>(1, word.size() / 3);
    return bestDist <= limit && bestDist > 0 && bestDist < word.size() ? best : std::string();
}

}  // namespace sprout
