#pragma once
// A VLab object (issue 50): a folder whose `specifications` file lists the object's files and the
// commands VLab runs, among them cpfg's command line (`cpfg -M plant.mat plant.l plant.v plant.a`).
// That line is read as cpfg reads its arguments (VLab's cpfg/control.c: its options, each with
// the arguments it takes, then the L-system, the view file and the animation file), so that the
// object opens with the L-system it runs. Its view file, animation file, material sets, colour
// maps and window size are applied to the plant and its picture (vlab_view.hpp); `-a` opens the
// viewer playing the animation file's frames; options of cpfg's own window and files are read
// for their arguments and left alone.
#include <optional>
#include <string>
#include <vector>

#include "core/language/diagnostic.hpp"

namespace sprout {

struct VlabObject {
    std::string specifications;         // the folder's `specifications` file
    std::string lsystem, view, animation;  // paths of the files cpfg's line names ("": none)
    // -M[n] FILE (material set n) and -m[n] FILE (colour map n); cpfg's later kind wins.
    struct ColourFile {
        int set = 1;
        bool material = false;
        std::string path;
        int line = 0, col = 0;  // of the option, in `specifications`
    };
    std::vector<ColourFile> colourFiles;
    int referenceSet = 1;      // -cN: `;(k)` is colour index 256 N + k
    int width = 0, height = 0; // -w W H: the window's size
    bool animate = false;               // -a: cpfg starts in animation mode (the viewer opens playing)
    std::string environment;            // `-e FILE.e`: the environment file's path (vlab_environment.hpp reads it)
    // At the cpfg line's options: errors (no cpfg line, an option cpfg does not know, no
    // L-system) and warnings (what is not read yet).
    std::vector<Diagnostic> diagnostics;
};

// The object in `folder`; nullopt when the folder has no `specifications` (not a VLab object).
std::optional<VlabObject> readVlabObject(const std::string& folder);

}  // namespace sprout
