#pragma once
// Files written for Python 2 (`print x`, `xrange`, `except E, e:`): L-Py 3 does not read them
// either, but Python's own message ("Missing parentheses in call to 'print'", "name 'xrange' is
// not defined") does not say why the file fails. python2Message says it, with the Python 3
// form to write. Pure C++ (no Python): the translation's library, tested without a model.
#include <optional>
#include <string>
#include <string_view>

namespace sprout::lpy {

// `error`: Python's message as "Type: text" (as the host writes it); `line`: the text of the
// file's line it points at. The message to show instead when that line is Python 2, or
// nothing when it is not.
std::optional<std::string> python2Message(std::string_view error, std::string_view line);

// Line `number` (from 1) of `text`, without its end; empty past the last line.
std::string_view lineOf(std::string_view text, int number);

}  // namespace sprout::lpy
