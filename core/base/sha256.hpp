#pragma once
// SHA-256 (FIPS 180-4) of a byte string, as 64 lowercase hex digits. The viewer remembers
// which L-Py models the user trusted by this hash of their text (app/viewer/state/trust.hpp).
#include <string>
#include <string_view>

namespace sprout {

std::string sha256Hex(std::string_view bytes);

}  // namespace sprout
