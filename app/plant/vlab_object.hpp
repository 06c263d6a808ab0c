#pragma once
// A VLab object (issue 50): a folder whose `specifications` file lists the object's files and the
// commands VLab runs, among them cpfg's command line (`cpfg -M plant.mat plant.l plant.v plant.a`).
// That line is read as cpfg reads its arguments (VLab's cpfg/control.c: its options, each with
// the arguments it takes, then the L-system, the view file and the animation file), so that the
// object opens with the L-system it runs. What the object's other files say (view, animation,
// materials, colour maps, environment, window) is not read yet: a warning names each.
#include <optional>
#include <string>
#include <vector>

#include "core/language/diagnostic.hpp"

namespace sprout {

struct VlabObject {
    std::string specifications;         // the folder's `specifications` file
    std::string lsystem, view, animation;  // paths of the files cpfg's line names ("": none)
    std::string environment;            // `-e FILE.e`: the environment file's path (vlab_environment.hpp reads it)
    // At the cpfg line's options: errors (no cpfg line, an option cpfg does not know, no
    // L-system) and warnings (what is not read yet).
    std::vector<Diagnostic> diagnostics;
};

// The object in `folder`; nullopt when the folder has no `specifications` (not a VLab object).
std::optional<VlabObject> readVlabObject(const std::string& folder);

}  // namespace sprout
