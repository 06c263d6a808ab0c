#include "core/derive/provenance.hpp"

#include <algorithm>

namespace sprout {

const Production* ruleOf(const Grammar& g, int rule) {
    if (rule >= 0 && size_t(rule) < g.rules.productions.size()) return &g.rules.productions[size_t(rule)];
    if (rule <= -2 && size_t(-(rule + 2)) < g.decomposition.productions.size()) return &g.decomposition.productions[size_t(-(rule + 2))];
    return nullptr;
}

int ruleLine(const Grammar& g, int rule) {
    const Production* p = ruleOf(g, rule);
    return p ? p->line : 0;
}

DerivationRecord DerivationRecord::of(Derivation& d) {
    DerivationRecord r;
    r.grammar = d.sharedGrammar();
    for (int k = 0; k <= d.stepsDerived(); ++k) {
        r.steps.push_back(d.step(k));
        r.origins.push_back(d.origins(k));
    }
    return r;
}

std::vector<LineageLink> lineage(Derivation& d, int step, std::uint32_t index) { return lineage(DerivationRecord::of(d), step, index); }

std::vector<LineageLink> lineage(const DerivationRecord& r, int step, std::uint32_t index) {
    std::vector<LineageLink> links;
    if (step < 0 || size_t(step) >= r.steps.size() || size_t(step) >= r.origins.size() || !r.grammar) return links;
    if (!r.origins[size_t(step)] || !r.steps[size_t(step)] || index >= r.steps[size_t(step)]->size()) return links;
    int k = step;
    std::uint32_t i = index;
    for (;;) {
        const auto& o = r.origins[size_t(k)];
        if (!o || !r.steps[size_t(k)] || i >= o->parent.size()) return {};
        const std::int32_t rule = o->rule.data()[i];
        if (rule == -1 && k > 0) {  // copied unchanged from the step before: made earlier
            i = o->parent.data()[i];
            --k;
            continue;
        }
        LineageLink link;
        link.step = k;
        link.index = i;
        link.symbol = r.steps[size_t(k)]->symbols.data()[i];
        link.rule = rule;
        link.ruleLine = ruleLine(*r.grammar, rule);
        links.push_back(link);
        if (k == 0) break;
        i = o->parent.data()[i];
        --k;
    }
    return links;
}

std::vector<std::int32_t> madeBy(const DerivationRecord& r, int step) {
    std::vector<std::int32_t> made, next;
    if (step < 0 || size_t(step) >= r.origins.size()) return made;
    for (int k = 0; k <= step; ++k) {
        const auto& o = r.origins[size_t(k)];
        if (!o) return {};
        next.resize(o->rule.size());
        for (size_t i = 0; i < next.size(); ++i) {
            const std::int32_t rule = o->rule.data()[i];
            const std::uint32_t parent = o->parent.data()[i];
            next[i] = rule != -1 || k == 0 ? rule : parent < made.size() ? made[parent] : -1;
        }
        made.swap(next);
    }
    return made;
}

void ContextMatches::add(std::uint32_t parent, const std::vector<std::uint32_t>& left, const std::vector<std::uint32_t>& right) {
    entries.push_back({parent, std::uint32_t(indices.size()), std::uint32_t(left.size()), std::uint32_t(right.size())});
    indices.insert(indices.end(), left.begin(), left.end());
    indices.insert(indices.end(), right.begin(), right.end());
}

void ContextMatches::sort() {
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.parent < b.parent; });
}

bool ContextMatches::find(std::uint32_t parent, std::vector<std::size_t>& left, std::vector<std::size_t>& right) const {
    auto it = std::lower_bound(entries.begin(), entries.end(), parent, [](const Entry& e, std::uint32_t p) { return e.parent < p; });
    if (it == entries.end() || it->parent != parent) return false;
    left.assign(indices.begin() + it->first, indices.begin() + it->first + it->left);
    right.assign(indices.begin() + it->first + it->left, indices.begin() + it->first + it->left + it->right);
    return true;
}

std::string describeLineage(const Grammar& g, const std::vector<LineageLink>& links) {
    std::string out;
    for (size_t k = 0; k < links.size(); ++k) {
        const LineageLink& l = links[k];
        if (k) out += " <- ";
        out += g.alphabet[l.symbol].name;
        if (l.step == 0 && l.rule == -1) out += " (axiom)";
        else out += " at step " + std::to_string(l.step) + " by line " + std::to_string(l.ruleLine);
    }
    return out;
}

}  // namespace sprout
