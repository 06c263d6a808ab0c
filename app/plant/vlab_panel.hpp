#pragma once
// A VLab object's control panel for its L-system (`panel panel.l | awkped plant.l` in its
// specifications): the panel file's sliders and buttons, each of which rewrites a `#define`
// of the L-system as VLab's panel and awkped do (message `d NAME %d DIVISOR`: the value over
// the divisor). The viewer's panel shows them (panel_sections.cpp).
#include <string>
#include <string_view>
#include <vector>

namespace sprout {

struct VlabPanelItem {
    bool slider = true;       // a SLIDER; else a BUTTON that sets `value`
    std::string label;        // its `name:`
    std::string define;       // the #define it rewrites
    double min = 0, max = 1;  // a slider's range, over the divisor
    double value = 0;         // the panel's value, over the divisor
    double divisor = 1;
};

struct VlabPanel {
    std::string name;                 // `panel name:`
    std::vector<VlabPanelItem> items;
    std::vector<std::string> problems;  // "panel.l:12: expected ..."
};

// The panel file's text; `fileName` names it in the problems.
VlabPanel readVlabPanel(std::string_view text, const std::string& fileName);

// The panels of the object in `folder` that drive its L-system `lsystemFile` (by file name):
// the specifications' `panel FILE ... | awkped LSYSTEM` commands.
std::vector<VlabPanel> vlabPanelsOf(const std::string& folder, const std::string& lsystemFile);

}  // namespace sprout
