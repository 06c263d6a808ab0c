#pragma once
// Reading a VLab object's .e file (`cpfg -e FILE.e`): the environment program it names and the
// communication it asks for, as VLab's comm library reads it (libs/comm/communication.c,
// ReadInEnvironmentalFile), with the program's own specification file (density.spec,
// enviro.spec, obstacles.dat) read as that program reads it. This is the one entry the object
// opener calls; the result goes to the parser as ParseOptions::environmentProgram.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/environment/cpfg_programs/program.hpp"
#include "core/language/diagnostic.hpp"

namespace sprout {

// A message about one of the files read (the .e file, the program's specification, its image).
struct EnviroDiagnostic {
    std::string file;
    Diagnostic diagnostic;
    std::string text() const { return formatDiagnostic(diagnostic, file); }
};

struct EnviroRead {
    // The program (a SilentProgram, answering nothing, when the .e file names one Sprout does
    // not provide or one that cannot start); null when the .e file itself cannot be read.
    // Not yet const: the opener may set what the view file says (EnvironmentProgram::afterStep).
    std::shared_ptr<EnvironmentProgram> program;
    std::vector<EnviroDiagnostic> diagnostics;  // warnings; an error when program is null
};

// The programs Sprout provides: honda81, ecosystem, clover, chiba and obcheck (the CelticKnot object's).
const std::vector<std::string>& providedEnvironmentPrograms();

// Reads `path` (a .e file) and the files its program names, in `folder` (where cpfg runs it: the
// object's folder; empty: the .e file's own). A name that leads outside that folder is refused.
EnviroRead readEnviroFile(const std::string& path, const std::string& folder = "");

// The same from the .e file's text; `read(name, error)` gives the program's files, which are
// named in messages as in `folder` (empty: the .e file's).
EnviroRead readEnviroText(const std::string& path, const std::string& text,
                          const std::function<std::optional<std::string>(const std::string&, std::string&)>& read,
                          const std::string& folder = "");

}  // namespace sprout
