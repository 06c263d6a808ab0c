#include "core/language/vlab/animation_file.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <string>

namespace sprout::vlab {
namespace {

std::string trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return std::string(s);
}

bool integer(const std::string& s, int& into) {
    size_t at = s.size() > 1 && s[0] == '+' ? 1 : 0;
    auto [end, ec] = std::from_chars(s.data() + at, s.data() + s.size(), into);
    return ec == std::errc() && end != s.data() + at;
}

// One interval as cpfg's sscanf patterns read it: `a-b step s`, `a-b rotate x y z`, `a`.
FrameInterval interval(const std::string& token) {
    FrameInterval f;
    int d = 0;
    std::sscanf(token.c_str(), "%d-%d step %d", &f.from, &f.to, &f.step);
    if (std::sscanf(token.c_str(), "%d-%d step %d rotate %lf %lf %lf", &d, &d, &d, &f.data[0], &f.data[1], &f.data[2]) == 6 ||
        std::sscanf(token.c_str(), "%d-%d rotate %lf %lf %lf", &d, &d, &f.data[0], &f.data[1], &f.data[2]) == 5)
        f.function = 1;
    if (std::sscanf(token.c_str(), "%d-%d step %d scale %lf %lf %lf", &d, &d, &d, &f.data[0], &f.data[1], &f.data[2]) == 6 ||
        std::sscanf(token.c_str(), "%d-%d scale %lf %lf %lf", &d, &d, &f.data[0], &f.data[1], &f.data[2]) == 5)
        f.function = 2;
    if (f.to < 0) f.to = f.from;
    return f;
}

}  // namespace

AnimationFile readAnimationFile(std::string_view text) {
    AnimationFile out;
    int number = 0;
    for (size_t start = 0; start < text.size();) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = text.substr(start, end - start);
        start = end + 1;
        ++number;
        const size_t colon = line.find(':');
        const std::string name = trimmed(line.substr(0, colon));
        if (name.empty()) continue;
        auto warn = [&](std::string m, Severity s = Severity::Warning) { out.diagnostics.push_back({number, 1, std::move(m), s}); };
        if (colon == std::string_view::npos) {
            warn("'" + name + "' is no animation command (expected 'name: value')");
            continue;
        }
        const std::string value = trimmed(line.substr(colon + 1));
        if (name == "frame intervals") {
            out.intervals.clear();
            for (size_t k = 0; k <= value.size();) {
                size_t comma = std::min(value.find(',', k), value.size());
                const std::string token = trimmed(std::string_view(value).substr(k, comma - k));
                k = comma + 1;
                if (token.empty()) continue;
                FrameInterval f = interval(token);
                if (f.from < 0) {
                    warn("'frame intervals:' expects intervals such as 1-10 step 2; found '" + token + "'", Severity::Error);
                    continue;
                }
                if (out.intervals.size() < 1000) out.intervals.push_back(f);
            }
            if (!out.intervals.empty()) {
                out.first = out.intervals.front().from;
                out.last = out.intervals.back().to;
            }
            continue;
        }
        const std::string word = trimmed(value.substr(0, value.find_first_of(" \t,")));
        if (word.empty()) {
            warn("'" + name + ":' has no value (cpfg skips it)");
            continue;
        }
        const bool on = word.rfind("on", 0) == 0;
        int n = 0;
        auto numberOf = [&](int& into) {
            if (integer(word, n)) into = n;
            else warn("'" + name + ":' expects a whole number; found '" + word + "'", Severity::Error);
            return integer(word, n);
        };
        if (name == "double buffer") out.doubleBuffer = on;
        else if (name == "clear between frames") out.clearBetweenFrames = on;
        else if (name == "scale between frames") out.scaleBetweenFrames = on;
        else if (name == "new view between frames") out.newViewBetweenFrames = on;
        else if (name == "center between frames") out.centerBetweenFrames = on;
        else if (name == "hcenter between frames") out.hcenterBetweenFrames = on;
        else if (name == "swap interval") numberOf(out.swapInterval);
        else if (name == "first frame") {
            if (numberOf(out.first)) out.first = std::max(out.first, 0);
        } else if (name == "last frame") {
            if (numberOf(out.last) && out.last >= 0 && out.last < out.first) out.last = out.first;
        } else if (name == "step") {
            if (numberOf(out.step) && out.step <= 0) out.step = 1;
        } else {
            warn("unknown animation command '" + name + ":' (cpfg skips it)");
        }
    }
    return out;
}

std::vector<int> AnimationFile::frames(int derivationLength) const {
    std::vector<int> out;
    auto add = [&](int from, int to, int by) {
        to = to < 0 ? derivationLength : std::min(to, derivationLength);
        for (int k = std::max(from, 0); k <= to && out.size() < 100000; k += std::max(by, 1)) out.push_back(k);
    };
    if (intervals.empty()) add(first, last, step);
    else
        for (const FrameInterval& f : intervals) add(f.from, f.to, f.step > 0 ? f.step : step);
    return out;
}

}  // namespace sprout::vlab
