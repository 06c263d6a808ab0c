#pragma once
// What the L-Py test files share: a model's diagnostics as one text, for failure messages.
#include <string>

#include "core/language/diagnostic.hpp"
#include "lpy/lpy.hpp"

namespace sprout {

inline std::string messages(const lpy::Model& m) {
    std::string out;
    for (const auto& d : m.diagnostics) out += formatDiagnostic(d, "model") + "\n";
    return out;
}

}  // namespace sprout
