#pragma once
// Helpers for core tests: parse (failing the test on errors) and derive to a string.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/derive/derive.hpp"
#include "core/language/grammar.hpp"

namespace sprout::test {

// A file's bytes, as they are.
inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

inline std::shared_ptr<const Grammar> grammarOf(const std::string& text) {
    ParseResult r = parse(text);
    for (const auto& d : r.diagnostics)
        if (d.severity == Severity::Error) ADD_FAILURE() << formatDiagnostic(d, "<test>");
    return r.grammar;
}

// Step n (default: the grammar's n) as printed by `sprout expand`.
inline std::string expand(const std::string& text, int n = -1, std::optional<std::uint64_t> seed = {}) {
    auto g = grammarOf(text);
    if (!g) return "<parse error>";
    DeriveOptions opts;
    opts.seed = seed;
    DeriveResult r = derive(g, n < 0 ? g->settings.iterations : n, opts);
    if (!r.outcome.ok()) return "<" + r.outcome.message + ">";
    return toString(*r.string, g->alphabet);
}

// All diagnostics of a text, formatted "line:col: message" (warnings marked).
inline std::vector<std::string> diagnosticsOf(const std::string& text) {
    std::vector<std::string> out;
    for (const auto& d : parse(text).diagnostics)
        out.push_back(std::to_string(d.line) + ":" + std::to_string(d.col) + ": " +
                      (d.severity == Severity::Warning ? "warning: " : "") + d.message);
    return out;
}

}  // namespace sprout::test
