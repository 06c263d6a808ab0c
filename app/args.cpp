#include "app/args.hpp"

#include <charconv>

namespace sprout {

Args::Args(int argc, char** argv, int first, std::set<std::string> flags, std::set<std::string> options) {
    for (int i = first; i < argc; ++i) {
        std::string a = argv[i];
        if (a.size() < 2 || a[0] != '-' || a == "-") {
            m_positionals.push_back(a);
            continue;
        }
        std::string value;
        bool inlineValue = false;
        if (auto eq = a.find('='); eq != std::string::npos) {
            value = a.substr(eq + 1);
            a = a.substr(0, eq);
            inlineValue = true;
        }
        if (flags.count(a) && !inlineValue) {
            m_flags.insert(a);
        } else if (options.count(a)) {
            if (!inlineValue) {
                if (i + 1 >= argc) {
                    m_error = a + " needs a value";
                    return;
                }
                value = argv[++i];
            }
            m_values[a] = value;
        } else {
            m_error = "unknown option " + a;
            return;
        }
    }
}

std::optional<std::string> Args::value(const std::string& name) const {
    auto it = m_values.find(name);
    if (it == m_values.end()) return std::nullopt;
    return it->second;
}

std::optional<std::int64_t> Args::integer(const std::string& name, std::int64_t min, std::int64_t max) {
    auto v = value(name);
    if (!v) return std::nullopt;
    std::int64_t out = 0;
    auto r = std::from_chars(v->data(), v->data() + v->size(), out);
    if (r.ec != std::errc() || r.ptr != v->data() + v->size() || out < min || out > max) {
        m_error = name + " expects a whole number from " + std::to_string(min) + " to " + std::to_string(max) +
                  ", not '" + *v + "'";
        return std::nullopt;
    }
    return out;
}

bool parseSize(const std::string& s, int& w, int& h) {
    // from_chars, not sscanf's %d (undefined past int's range).
    const std::size_t x = s.find_first_of("xX");
    if (x == std::string::npos) return false;
    int a = 0, b = 0;
    const char *begin = s.data(), *end = s.data() + s.size();
    auto ra = std::from_chars(begin, begin + x, a);
    auto rb = std::from_chars(begin + x + 1, end, b);
    if (ra.ec != std::errc() || ra.ptr != begin + x || rb.ec != std::errc() || rb.ptr != end) return false;
    if (a < 16 || b < 16 || a > 8192 || b > 8192) return false;
    w = a;
    h = b;
    return true;
}

}  // namespace sprout
