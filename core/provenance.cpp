#include "core/provenance.hpp"

namespace sprout {

int ruleLine(const Grammar& g, int rule) {
    if (rule >= 0 && size_t(rule) < g.rules.productions.size()) return g.rules.productions[size_t(rule)].line;
    if (rule <= -2 && size_t(-(rule + 2)) < g.decomposition.productions.size())
        return g.decomposition.productions[size_t(-(rule + 2))].line;
    return 0;
}

std::vector<LineageLink> lineage(Derivation& d, int step, std::uint32_t index) {
    std::vector<LineageLink> links;
    if (step < 0 || step > d.stepsDerived()) return links;
    auto s = d.step(step);
    if (!d.origins(step) || !s || index >= s->size()) return links;
    int k = step;
    std::uint32_t i = index;
    for (;;) {
        auto o = d.origins(k);
        if (!o || i >= o->parent.size()) return {};
        const std::int32_t rule = o->rule.data()[i];
        if (rule == -1 && k > 0) {  // copied unchanged from the step before: made earlier
            i = o->parent.data()[i];
            --k;
            continue;
        }
        LineageLink link;
        link.step = k;
        link.index = i;
        link.symbol = d.step(k)->symbols.data()[i];
        link.rule = rule;
        link.ruleLine = ruleLine(d.grammar(), rule);
        links.push_back(link);
        if (k == 0) break;
        i = o->parent.data()[i];
        --k;
    }
    return links;
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
