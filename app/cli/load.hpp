#pragma once
// A subcommand's plant: opened by app/plant/ (a file, "-" for standard input, or a preset's
// name), what is wrong printed to standard error as it is found.
#include <optional>
#include <string>

#include "app/plant/open.hpp"

namespace sprout::cli {

// Prints one line of a report to standard error.
void printReport(const std::string& line);
// openPlant with its report printed; nullopt when the grammar has errors or cannot be read.
std::optional<LoadedGrammar> loadGrammar(const std::string& source, const LoadOptions& options = {});

}  // namespace sprout::cli
