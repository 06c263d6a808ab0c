// Sprout built without Python: L-Py models cannot run (lpy/CMakeLists.txt).
#include "lpy/lpy.hpp"

namespace sprout::lpy {

bool pythonAvailable() { return false; }

Model runModel(std::string_view, const RunOptions&) {
    Model out;
    out.diagnostics.push_back({0, 0, "this Sprout was built without Python: install python3-dev and pybind11-dev and build again to run L-Py models",
                               Severity::Error});
    return out;
}

void installOpenalea() {}

void setScenePlantMaker(void*) {}

std::shared_ptr<const Grammar> drawingOf(void*, void*) { return nullptr; }

}  // namespace sprout::lpy
