#pragma once
// An L-Py model's scalar parameters created, renamed and deleted (issue 52), as L-Py Studio's
// scalar editor does: in the `scalars = [...]` list of its INITIALISATION part (made, with the
// lines Studio writes after it, when the model has none). Their values are text_edit.hpp's
// (lpyScalars, setLpyScalar).
#include <string>
#include <string_view>

#include "app/plant/text_edit.hpp"

namespace sprout {

// The text with scalar `s` added (its name, kind, value, range; a Float with two decimals as
// Studio gives it), or "" and `error` (a name that is no Python identifier, or taken).
std::string addLpyScalar(std::string_view text, const LpyScalar& s, std::string& error);
// The text with the scalar's name changed in the list (what the model's code calls it is the
// model's own: Studio renames the parameter only), or "" and `error`.
std::string renameLpyScalar(std::string_view text, std::string_view name, std::string_view newName, std::string& error);
// The text without that scalar, or "" and `error`.
std::string removeLpyScalar(std::string_view text, std::string_view name, std::string& error);

}  // namespace sprout
