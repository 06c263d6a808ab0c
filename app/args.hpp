#pragma once
// Command-line arguments of one subcommand: positionals and --options with values.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace sprout {

class Args {
public:
    // `flags` take no value; `options` take one (given as "--opt V" or "--opt=V").
    Args(int argc, char** argv, int first, std::set<std::string> flags, std::set<std::string> options);

    const std::string& error() const { return m_error; }
    const std::vector<std::string>& positionals() const { return m_positionals; }
    bool flag(const std::string& name) const { return m_flags.count(name) > 0; }
    std::optional<std::string> value(const std::string& name) const;
    // Parses an integer option; sets error() when malformed or out of range.
    std::optional<std::int64_t> integer(const std::string& name, std::int64_t min, std::int64_t max);

private:
    std::vector<std::string> m_positionals;
    std::set<std::string> m_flags;
    std::map<std::string, std::string> m_values;
    std::string m_error;
};

// "WIDTHxHEIGHT" (or X), each from 16 to 8192; false, leaving w and h, when it is not that.
// The one reader of picture sizes: render's and the viewer's --size, a script's screenshot.
bool parseSize(const std::string& s, int& w, int& h);

}  // namespace sprout
