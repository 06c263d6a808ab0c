#pragma once
// Loading a grammar for a subcommand: a file path, "-" for standard input, or a preset name.
#include <optional>
#include <string>

#include "core/derive.hpp"
#include "core/forest.hpp"
#include "core/grammar.hpp"

namespace sprout::cli {

struct LoadedGrammar {
    std::string displayName;  // used in FILE:line:col messages
    std::string text;         // the grammar as written
    std::shared_ptr<const Grammar> grammar;
};

// Prints diagnostics (errors and warnings) to stderr; nullopt when the grammar has errors
// or cannot be read.
std::optional<LoadedGrammar> loadGrammar(const std::string& source);

// What a PNG written by Sprout holds: "lsys", "ifs" or "forest"; empty for any other file.
std::string pngKind(const std::string& path);

// A forest scene (.forest file or scene preset) built into one geometry; `text` is the
// scene as written. Prints diagnostics; false when it cannot be built.
bool buildForestScene(const std::string& source, std::optional<std::uint64_t> seed, const DeriveLimits& limits,
                      Geometry& geometry, ForestStats& stats, std::string& text);

}  // namespace sprout::cli
