#include "app/plant/vlab_environment.hpp"

#include <filesystem>
#include <sstream>

#include "app/plant/vlab_object.hpp"
#include "core/base/read_file.hpp"

namespace sprout {

namespace {

// cpfg's view file: `environment display: before` (interpret.c, ReadViewData; only its first six
// letters are compared). The rest of the view file is read elsewhere.
bool displaysBefore(const std::string& viewFile) {
    if (viewFile.empty()) return false;
    std::istringstream in(readFile(viewFile).value_or(""));
    const std::string key = "environment display:";
    for (std::string line; std::getline(in, line);) {
        const size_t at = line.find_first_not_of(" \t");
        if (at == std::string::npos || line.compare(at, key.size(), key) != 0) continue;
        const size_t word = line.find_first_not_of(" \t", at + key.size());
        return word != std::string::npos && line.compare(word, 6, "before") == 0;
    }
    return false;
}

}  // namespace

ObjectEnvironment readObjectEnvironment(const std::string& enviroFile, const std::string& viewFile, const std::string& folder) {
    ObjectEnvironment out;
    EnviroRead r = readEnviroFile(enviroFile, folder);
    if (r.program) r.program->afterStep = displaysBefore(viewFile);
    out.program = std::move(r.program);
    for (const EnviroDiagnostic& d : r.diagnostics) {
        out.messages.push_back(d.text());
        out.failed = out.failed || d.diagnostic.severity == Severity::Error;
    }
    return out;
}

ObjectEnvironment objectEnvironment(const std::string& lsystemPath) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path l(lsystemPath);
    const fs::path folder = l.has_parent_path() ? l.parent_path() : fs::path(".");
    if (!fs::is_regular_file(folder / "specifications", ec)) return {};
    std::optional<VlabObject> object = readVlabObject(folder.string());
    if (!object || object->environment.empty() || object->lsystem.empty()) return {};
    if (!fs::equivalent(fs::path(object->lsystem), l, ec)) return {};
    return readObjectEnvironment(object->environment, object->view, folder.string());
}

}  // namespace sprout
