#include "app/presets.hpp"

namespace sprout {

std::optional<std::string_view> presetText(std::string_view name) {
    if (name.ends_with(".lsys")) name.remove_suffix(5);
    for (const auto& f : embeddedPresets())
        if (f.stem == name) return f.data;
    return std::nullopt;
}

std::vector<std::string> presetNames() {
    std::vector<std::string> names;
    for (const auto& f : embeddedPresets()) names.emplace_back(f.stem);
    return names;
}

}  // namespace sprout
