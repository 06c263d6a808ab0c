#include "core/language/source.hpp"

namespace sprout {

int columnOf(std::string_view line, size_t offset) {
    int col = 1;
    for (size_t i = 0; i < offset && i < line.size(); ++i)
        if ((static_cast<unsigned char>(line[i]) & 0xC0) != 0x80) ++col;
    return col;
}

Diagnostic DiagnosticSink::make(const SourceLine& line, std::string_view at, std::string message,
                                Severity s) {
    size_t offset = 0;
    if (at.data() >= line.text.data() && at.data() <= line.text.data() + line.text.size())
        offset = size_t(at.data() - line.text.data());
    std::string_view shown = line.original.empty() ? line.text : line.original;
    return {line.number, columnOf(shown, offset), std::move(message), s};
}

void DiagnosticSink::error(const SourceLine& line, std::string_view at, std::string message) {
    m_diags.push_back(make(line, at, std::move(message), Severity::Error));
}

void DiagnosticSink::warning(const SourceLine& line, std::string_view at, std::string message) {
    m_diags.push_back(make(line, at, std::move(message), Severity::Warning));
}

size_t DiagnosticSink::errorCount() const {
    size_t n = 0;
    for (const auto& d : m_diags) n += d.severity == Severity::Error;
    return n;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
    while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
    return s;
}

}  // namespace sprout
