#include "core/language/alphabet.hpp"

namespace sprout {

Alphabet::Alphabet() {
    intern("[", 0);
    intern("]", 0);
    intern("%", 0);
}

std::optional<NameId> Alphabet::findName(std::string_view name) const {
    auto it = m_nameIds.find(std::string(name));
    if (it == m_nameIds.end()) return std::nullopt;
    return it->second;
}

std::optional<SymbolId> Alphabet::find(std::string_view name, int arity) const {
    auto n = findName(name);
    if (!n) return std::nullopt;
    auto it = m_ids.find((std::uint64_t(*n) << 8) | std::uint64_t(arity));
    if (it == m_ids.end()) return std::nullopt;
    return it->second;
}

std::optional<SymbolId> Alphabet::intern(std::string_view name, int arity) {
    if (auto id = find(name, arity)) return id;
    if (m_symbols.size() >= kMaxSymbols || arity < 0 || arity > kMaxArity) return std::nullopt;
    NameId nameId;
    if (auto n = findName(name)) {
        nameId = *n;
    } else {
        nameId = NameId(m_names.size());
        m_names.emplace_back(name);
        m_nameIds.emplace(std::string(name), nameId);
    }
    SymbolId id = SymbolId(m_symbols.size());
    m_symbols.push_back({std::string(name), nameId, std::uint8_t(arity)});
    m_ids.emplace((std::uint64_t(nameId) << 8) | std::uint64_t(arity), id);
    return id;
}

double Alphabet::internString(std::string_view text) {
    for (size_t i = 0; i < m_strings.size(); ++i)
        if (m_strings[i] == text) return double(i);
    m_strings.emplace_back(text);
    return double(m_strings.size() - 1);
}

}  // namespace sprout
