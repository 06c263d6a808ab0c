#include "app/plant/presets.hpp"

namespace sprout {

std::optional<std::string_view> presetText(std::string_view name) {
    if (name.ends_with(".lsys")) name.remove_suffix(5);
    else if (name.ends_with(".ifs")) name.remove_suffix(4);
    else if (name.ends_with(".forest")) name.remove_suffix(7);
    else if (name.ends_with(".lpy")) name.remove_suffix(4);
    else if (name.ends_with(".l")) name.remove_suffix(2);
    for (const auto& f : embeddedPresets())
        if (f.stem == name) return f.data;
    return std::nullopt;
}

std::vector<std::string> presetNames() {
    std::vector<std::string> names;
    for (const auto& f : embeddedPresets())
        // .l: the cpfg family; .lpy: L-Py models (Sprout's own, run without asking)
        if (f.fileName.ends_with(".lsys") || f.fileName.ends_with(".l") || f.fileName.ends_with(".lpy")) names.emplace_back(f.stem);
    return names;
}

std::vector<std::string> ifsPresetNames() {
    std::vector<std::string> names;
    for (const auto& f : embeddedPresets())
        if (f.fileName.ends_with(".ifs")) names.emplace_back(f.stem);
    return names;
}

std::vector<std::string> scenePresetNames() {
    std::vector<std::string> names;
    for (const auto& f : embeddedPresets())
        if (f.fileName.ends_with(".forest")) names.emplace_back(f.stem);
    return names;
}

bool isIfsPreset(std::string_view name) {
    if (name.ends_with(".ifs")) name.remove_suffix(4);
    for (const auto& f : embeddedPresets())
        if (f.stem == name) return f.fileName.ends_with(".ifs");
    return false;
}

}  // namespace sprout
