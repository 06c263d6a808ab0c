#pragma once
// Slider <-> text round trip: a slider writes its value back into the grammar text, so the
// text stays the single source of truth (and what is saved is what is shown).
#include <optional>
#include <string>
#include <string_view>

namespace sprout::viewer {

// Sets `key: value` in `text`: replaces the value of the first line with that key (keeping
// any jitter `~ sigma`), or inserts the line before the axiom when there is none.
std::string setDirective(std::string_view text, std::string_view key, std::string_view value);

// Sets the value of `define: name = value` / `#define name value`.
std::string setDefine(std::string_view text, std::string_view name, std::string_view value);

// The value text of the first `key:` line, if any.
std::optional<std::string> directiveValue(std::string_view text, std::string_view key);

// Shortest text for a slider value (3 significant decimals is what a slider can set).
std::string formatValue(double v);

}  // namespace sprout::viewer
