// Reading the programs' specification files as their C reads them (spec_file.hpp).
#include "core/environment/cpfg_programs/spec_file.hpp"

#include <cstdlib>

namespace sprout::cpfgprog {

void Sink::warning(int line, std::string message) const {
    if (out) out->push_back({file, {line, line > 0 ? 1 : 0, std::move(message), Severity::Warning}});
}

void Sink::error(int line, std::string message) const {
    if (out) out->push_back({file, {line, line > 0 ? 1 : 0, std::move(message), Severity::Error}});
}

std::vector<SpecLine> specLines(std::string_view text) {
    std::vector<SpecLine> out;
    int number = 0;
    for (size_t at = 0; at < text.size();) {
        size_t end = text.find('\n', at);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(at, end - at);
        at = end + 1;
        ++number;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        // strtok(line, "\t:"): the keyword is what comes before the first ':' or tab, after any.
        size_t k = line.find_first_not_of("\t:");
        if (k == std::string_view::npos) continue;  // a blank line
        size_t e = line.find_first_of("\t:", k);
        if (e == std::string_view::npos) e = line.size();
        SpecLine s;
        s.number = number;
        s.keyword = std::string(line.substr(k, e - k));
        if (s.keyword.find_first_not_of(" ") == std::string::npos) continue;
        s.rest = e < line.size() ? std::string(line.substr(e + 1)) : std::string();
        s.restCol = int(e) + 2;
        out.push_back(std::move(s));
    }
    return out;
}

std::vector<Token> tokensOf(const SpecLine& line, std::string_view delims) {
    std::vector<Token> out;
    const std::string& r = line.rest;
    for (size_t i = 0; i < r.size();) {
        while (i < r.size() && delims.find(r[i]) != std::string_view::npos) ++i;
        const size_t b = i;
        while (i < r.size() && delims.find(r[i]) == std::string_view::npos) ++i;
        if (i > b) out.push_back({r.substr(b, i - b), line.restCol + int(b)});
    }
    return out;
}

double numberOf(const Token& t, const SpecLine& line, const Sink& sink, const char* expected) {
    const char* s = t.text.c_str();
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    if (end == s)
        sink.warning(line.number, "'" + line.keyword + "': expected " + expected + ", not '" + t.text + "' (read as 0)");
    else if (*end)
        sink.warning(line.number, "'" + line.keyword + "': expected " + expected + ", not '" + t.text + "' (read as " +
                                      std::string(s, size_t(end - s)) + ")");
    return end == s ? 0.0 : v;
}

int toInt(double v) {
    if (!(v > -2e9 && v < 2e9)) return v > 0 ? 2'000'000'000 : -2'000'000'000;
    return int(v);
}

std::int64_t gridCells(std::initializer_list<int> sizes, std::int64_t cap) {
    std::int64_t cells = 1;
    for (int n : sizes) {
        if (n < 1) return 0;
        if (cells > cap / n) return cap + 1;
        cells *= n;
    }
    return cells > cap ? cap + 1 : cells;
}

void unknownKeyword(const SpecLine& line, const std::vector<std::string>& keywords, const std::string& program,
                    const Sink& sink) {
    std::string list;
    for (const std::string& k : keywords) list += (list.empty() ? "" : ", ") + ("'" + k + "'");
    std::string near = closestMatch(line.keyword, keywords);
    sink.warning(line.number, program + " has no setting '" + line.keyword + "' (it passes over this line)" +
                                  (near.empty() ? "" : "; did you mean '" + near + "'?") + " Its settings: " + list);
}

}  // namespace sprout::cpfgprog
