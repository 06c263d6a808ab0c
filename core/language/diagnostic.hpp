#pragma once
// User mistakes are values: every problem found in a grammar carries its position and a
// message a student can act on. Nothing in core/ throws across its API.
#include <string>
#include <vector>

namespace sprout {

enum class Severity { Error, Warning };

struct Diagnostic {
    int line = 0;  // 1-based; 0 when the problem has no position (e.g. a derivation limit)
    int col = 0;   // 1-based, counted in characters (UTF-8 code points)
    std::string message;
    Severity severity = Severity::Error;
};

// "FILE:line:col: message" (or "FILE: message" without a position), the form compilers use
// so that editors can jump to it.
std::string formatDiagnostic(const Diagnostic& d, const std::string& file);

bool hasErrors(const std::vector<Diagnostic>& diags);

// The closest candidate by edit distance, or "" when none is close enough to suggest.
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace sprout
