#pragma once
// A VLab object's environment (`cpfg -e FILE.e`): the program its .e file names, read and started
// as Sprout's own (core/environment/cpfg_programs/), for the parser to hand its ?E modules to.
#include <memory>
#include <string>
#include <vector>

#include "core/environment/cpfg_programs/enviro_file.hpp"

namespace sprout {

struct ObjectEnvironment {
    std::shared_ptr<const EnvironmentProgram> program;  // null: no -e, or its file cannot be read
    std::vector<std::string> messages;                   // "FILE:line: ..." each
    bool failed = false;                                 // a message is an error
};

// The environment of the object whose cpfg line runs the L-system `lsystemPath` (the folder
// beside it has a `specifications` naming it, with -e); none for any other file.
ObjectEnvironment objectEnvironment(const std::string& lsystemPath);

// The environment file `enviroFile` read (readEnviroFile; the program's files in `folder`, the
// object's, where cpfg runs it), its messages formatted; when the view file `viewFile` says
// `environment display: before`, the program is asked after each step (afterStep).
ObjectEnvironment readObjectEnvironment(const std::string& enviroFile, const std::string& viewFile = "",
                                        const std::string& folder = "");

}  // namespace sprout
