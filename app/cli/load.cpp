#include "app/cli/load.hpp"

#include <iostream>

namespace sprout::cli {

void printReport(const std::string& line) { std::cerr << line << "\n"; }

std::optional<LoadedGrammar> loadGrammar(const std::string& source, const LoadOptions& options) {
    return openPlant(source, options, printReport);
}

}  // namespace sprout::cli
