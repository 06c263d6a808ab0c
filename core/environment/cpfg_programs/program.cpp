// What crosses between cpfg and its environment program (VLab's libs/comm): the turtle printed
// with the .e file's formats and read back, the parameters printed with %g and read back.
#include "core/environment/cpfg_programs/program.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace sprout {

bool formatTurtleValues(const std::string& format, const float* values, int n, std::string& out, std::string* error) {
    out.clear();
    int used = 0;
    for (size_t i = 0; i < format.size(); ++i) {
        if (format[i] != '%') {
            out += format[i];
            continue;
        }
        if (i + 1 < format.size() && format[i + 1] == '%') {
            out += '%';
            ++i;
            continue;
        }
        // %[flags][width][.precision][l|L]conversion
        size_t j = i + 1;
        // (strchr finds the terminator too: a NUL in the format is no flag and no conversion)
        while (j < format.size() && format[j] != '\0' && std::strchr("-+ #0", format[j])) ++j;
        int width = 0, precision = 0;
        while (j < format.size() && format[j] >= '0' && format[j] <= '9') width = std::min(width * 10 + (format[j++] - '0'), 1000);
        if (j < format.size() && format[j] == '.') {
            ++j;
            while (j < format.size() && format[j] >= '0' && format[j] <= '9') precision = std::min(precision * 10 + (format[j++] - '0'), 1000);
        }
        std::string spec = format.substr(i, j - i);
        while (j < format.size() && (format[j] == 'l' || format[j] == 'L')) ++j;
        if (j >= format.size() || format[j] == '\0' || !std::strchr("eEfFgG", format[j])) {
            if (error)
                *error = "expected a number's conversion (%f, %g or %e, with a width and a precision if any) at '" +
                         format.substr(i, std::min<size_t>(j + 1, format.size()) - i) + "'";
            return false;
        }
        if (width > 64 || precision > 64) {
            if (error) *error = "the width or precision of '" + format.substr(i, j + 1 - i) + "' is over 64";
            return false;
        }
        if (used >= 3 || used >= n) {
            if (error) *error = "it prints " + std::to_string(n) + " number" + (n > 1 ? "s" : "") + " at most";
            return false;
        }
        spec += format[j];
        char buf[160];
        std::snprintf(buf, sizeof buf, spec.c_str(), double(values[used++]));
        out += buf;
        i = j;
    }
    return true;
}

float throughText(double value) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", double(float(value)));
    return float(std::atof(buf));
}

namespace {

// comm_slave.c: skip the characters before the format's first conversion, then sscanf "%f %f %f".
void readBack(const std::string& format, const float* values, int n, TurtleField& field) {
    if (format.empty()) return;
    int count = 0;
    size_t skip = std::string::npos;
    for (size_t i = 0; i < format.size(); ++i)
        if (format[i] == '%') {
            if (i + 1 < format.size() && format[i + 1] == '%') {
                ++i;
                continue;
            }
            if (skip == std::string::npos) skip = i;
            ++count;
        }
    field.count = std::min(count, 3);
    if (count == 0) return;
    std::string text;
    if (!formatTurtleValues(format, values, n, text, nullptr)) return;  // checked when the .e file was read
    const char* p = text.c_str() + std::min(skip, text.size());
    for (int k = 0; k < 3; ++k) {
        char* end = nullptr;
        const float v = std::strtof(p, &end);
        if (end == p) break;  // sscanf stops: the values after keep what they were
        field.v[size_t(k)] = v;
        p = end;
    }
}

class SilentRun : public ProgramRun {
public:
    void pass(std::vector<ProgramQuery>&) override {}
};

}  // namespace

void EnvironmentProgram::receive(const float position[3], const float heading[3], const float left[3], const float up[3],
                                 ProgramQuery& q) const {
    readBack(formats.position, position, 3, q.position);
    readBack(formats.heading, heading, 3, q.heading);
    readBack(formats.left, left, 3, q.left);
    readBack(formats.up, up, 3, q.up);
}

std::unique_ptr<ProgramRun> SilentProgram::start() const { return std::make_unique<SilentRun>(); }

}  // namespace sprout
