#pragma once
// Which rule made this branch? The lineage of one module of a derived string, from the
// origins a derivation records (DeriveOptions::trackOrigins): the step that made it, the rule
// (and its line in the file), and its ancestors back to the axiom. Used by picking in the
// viewer and by the derivation inspector.
#include <cstdint>
#include <string>
#include <vector>

#include "core/derive/derive.hpp"

namespace sprout {

struct LineageLink {
    int step = 0;              // the step that made this module (0: the axiom)
    std::uint32_t index = 0;   // its index in that step's string
    SymbolId symbol = 0;
    int rule = -1;             // as Origins::rule: >= 0 a production, <= -2 a decomposition one, -1 none
    int ruleLine = 0;          // the rule's line in the file; 0 for the axiom
};

// Where the contexts of context-sensitive rules matched, kept by a derivation whose rules
// cannot be matched again from its record (L-Py's, whose rules are Python): for each module
// of the step read that such a rule rewrote, the modules of that step its left and right
// contexts matched.
struct ContextMatches {
    struct Entry {
        std::uint32_t parent = 0;            // the module rewritten
        std::uint32_t first = 0, left = 0, right = 0;  // indices[first, +left): left, then right
    };
    std::vector<Entry> entries;  // ascending by parent (sort() after adding)
    std::vector<std::uint32_t> indices;
    void add(std::uint32_t parent, const std::vector<std::uint32_t>& left, const std::vector<std::uint32_t>& right);
    void sort();
    // The left and right contexts that matched where `parent` was rewritten; false if none.
    bool find(std::uint32_t parent, std::vector<std::size_t>& left, std::vector<std::size_t>& right) const;
};

// The steps of a derivation and their origins, kept apart from it (shared pointers to
// immutable data): the viewer hands it to the window thread while the worker goes on.
struct DerivationRecord {
    std::shared_ptr<const Grammar> grammar;
    std::vector<std::shared_ptr<const ModuleString>> steps;
    std::vector<std::shared_ptr<const Origins>> origins;
    // contexts[k]: where contexts matched in making step k from step k - 1, when kept
    // (ContextMatches; empty or shorter for a grammar, whose rules say it again).
    std::vector<std::shared_ptr<const ContextMatches>> contexts;
    static DerivationRecord of(Derivation& d);  // steps 0 .. the last one derived
};

// links[0] is the module itself where it was made; each next one is the module it came from,
// ending at a module of the axiom. Empty when the derivation keeps no origins or the module is
// not there.
std::vector<LineageLink> lineage(const DerivationRecord& record, int step, std::uint32_t index);
std::vector<LineageLink> lineage(Derivation& derivation, int step, std::uint32_t index);

// For each module of step `step`, the rule that made it (as Origins::rule; -1 for modules of
// the axiom never rewritten): "everything this rule made" in one pass over the steps.
std::vector<std::int32_t> madeBy(const DerivationRecord& record, int step);

// The line of an encoded rule in the grammar's file (0: none).
int ruleLine(const Grammar& grammar, int rule);
// The production an Origins rule index names (as ruleLine), or nullptr.
const Production* ruleOf(const Grammar& grammar, int rule);

// "A(1.5) made at step 3 by line 7 <- B at step 2 by line 5 <- A (axiom)", for the panel and tests.
std::string describeLineage(const Grammar& grammar, const std::vector<LineageLink>& links);

}  // namespace sprout
