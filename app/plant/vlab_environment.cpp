#include "app/plant/vlab_environment.hpp"

#include <filesystem>

#include "app/plant/vlab_object.hpp"

namespace sprout {

ObjectEnvironment readObjectEnvironment(const std::string& enviroFile) {
    ObjectEnvironment out;
    EnviroRead r = readEnviroFile(enviroFile);
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
    return readObjectEnvironment(object->environment);
}

}  // namespace sprout
