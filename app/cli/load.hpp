#pragma once
// Loading a grammar for a subcommand: a file path, "-" for standard input, or a preset name.
#include <optional>
#include <string>

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

}  // namespace sprout::cli
