#pragma once
// The preset plants in presets/, embedded in the binary so Sprout works from any directory.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/embedded_file.hpp"

namespace sprout {

std::span<const EmbeddedFile> embeddedPresets();  // generated
std::optional<std::string_view> presetText(std::string_view name);
// L-system presets (.lsys) by name; IFS presets (.ifs) are listed apart.
std::vector<std::string> presetNames();
std::vector<std::string> ifsPresetNames();
std::vector<std::string> scenePresetNames();  // forests (.forest)
bool isIfsPreset(std::string_view name);
// The plant the viewer opens on.
constexpr std::string_view kDefaultPreset = "bush_3d";

}  // namespace sprout
