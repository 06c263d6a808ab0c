#pragma once
// The symbols of one grammar. A module is a name plus a fixed number of parameters; `F` and
// `F(2)` are two symbols with the same name, so a module's parameter count follows from its
// symbol id and a string needs no per-module offsets (2 bytes per module, 8 per parameter).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace sprout {

using SymbolId = std::uint16_t;
using NameId = std::uint16_t;

struct SymbolInfo {
    std::string name;
    NameId nameId = 0;  // shared by all arities of one name (contexts and `ignore` match names)
    std::uint8_t arity = 0;
    // Parameters written as quoted names (`SetContour("leaf")`): bit k for parameter k, whose
    // number is an index into Alphabet::strings(); printed back as the name.
    std::uint32_t nameArgs = 0;
};

class Alphabet {
public:
    static constexpr SymbolId kPush = 0;  // [
    static constexpr SymbolId kPop = 1;   // ]
    static constexpr SymbolId kCut = 2;   // %
    static constexpr size_t kMaxSymbols = 65535;
    static constexpr int kMaxArity = 32;
    // cpfg's strings keep parameters as floats: written back as the shortest text that gives
    // the same float (0.6, not 0.6000000238418579).
    bool floatParameters = false;

    Alphabet();

    // The id of (name, arity), adding it when new; nullopt when the alphabet is full.
    std::optional<SymbolId> intern(std::string_view name, int arity);
    std::optional<SymbolId> find(std::string_view name, int arity) const;
    std::optional<NameId> findName(std::string_view name) const;

    const SymbolInfo& operator[](SymbolId id) const { return m_symbols[id]; }
    size_t size() const { return m_symbols.size(); }
    size_t nameCount() const { return m_names.size(); }
    const std::string& name(NameId id) const { return m_names[id]; }
    // Quoted names given as parameters: the number that stands for `text`, and its text back.
    double internString(std::string_view text);
    const std::vector<std::string>& strings() const { return m_strings; }
    void markNameArg(SymbolId id, int k) { m_symbols[id].nameArgs |= std::uint32_t(1) << k; }

private:
    std::vector<SymbolInfo> m_symbols;
    std::vector<std::string> m_names;
    std::unordered_map<std::string, NameId> m_nameIds;
    std::unordered_map<std::uint64_t, SymbolId> m_ids;  // (nameId << 8 | arity) -> symbol
    std::vector<std::string> m_strings;
};

}  // namespace sprout
