// The derivation inspector: the string of any step, a range at a time (a 25 M-module string is
// never copied: 256 modules are read where they are), each module coloured by the rule that
// made it, with the module count of every step, a search, and for a chosen module its rule,
// where it came from and, for a context-sensitive rule, which context matched. Choosing a
// module of the drawn step picks it in the 3D view.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "app/viewer/window/app.hpp"
#include "app/plant/text_edit.hpp"
#include "core/derive/step_rewriter.hpp"

namespace sprout::viewer {
namespace {

constexpr std::uint64_t kRows = 256;         // modules listed at once
constexpr std::uint64_t kCheckpoint = 4096;  // parameter offsets kept every this many modules

ImVec4 ruleColour(std::int32_t rule) {
    if (rule == -1) return ImVec4(0.62f, 0.62f, 0.62f, 1);  // the axiom's, never rewritten
    static const ImVec4 hues[] = {{0.45f, 0.85f, 0.45f, 1}, {0.95f, 0.65f, 0.3f, 1}, {0.45f, 0.7f, 1.0f, 1},
                                  {0.95f, 0.45f, 0.7f, 1},  {0.9f, 0.9f, 0.4f, 1},   {0.6f, 0.5f, 1.0f, 1},
                                  {0.4f, 0.9f, 0.9f, 1},    {1.0f, 0.5f, 0.45f, 1}};
    const int k = rule >= 0 ? rule : -(rule + 2) + 5;
    return hues[size_t(k) % std::size(hues)];
}

// Parameter offsets every kCheckpoint modules, so that any module's parameters are found
// without walking the string from its start.
std::vector<std::uint64_t> checkpointsOf(const ModuleString& s, const Alphabet& a) {
    std::vector<std::uint64_t> out(size_t(s.size() / kCheckpoint + 1), 0);
    std::uint64_t p = 0;
    for (std::uint64_t i = 0; i < s.size(); ++i) {
        if (i % kCheckpoint == 0) out[size_t(i / kCheckpoint)] = p;
        p += a[s.symbols.data()[i]].arity;
    }
    return out;
}

// "F(1.5)": module i, its parameters found from the nearest checkpoint.
std::string moduleAt(const ModuleString& s, const Alphabet& a, const std::vector<std::uint64_t>& checkpoints, std::uint64_t i) {
    std::uint64_t p = checkpoints[size_t(i / kCheckpoint)];
    for (std::uint64_t k = i / kCheckpoint * kCheckpoint; k < i; ++k) p += a[s.symbols.data()[k]].arity;
    std::string out;
    appendModule(out, a[s.symbols.data()[i]], s.params.data() + p, &a);
    return out;
}

// What the inspector says of a chosen module: itself, the rule that made it and, for a rule
// with a context, the modules of the step before that the context matched.
std::vector<std::string> describe(const DerivationRecord& record, int step, std::uint32_t chosen,
                                  const std::vector<std::uint64_t>& checkpoints) {
    const Grammar& g = *record.grammar;
    std::vector<std::string> out{moduleAt(*record.steps[size_t(step)], g.alphabet, checkpoints, chosen)};
    const auto links = lineage(record, step, chosen);
    if (links.empty()) return out;
    const LineageLink& made = links[0];
    if (made.ruleLine == 0) {
        out.push_back("from the axiom (module " + std::to_string(made.index) + ")");
        return out;
    }
    out.push_back("made at step " + std::to_string(made.step) + " by line " + std::to_string(made.ruleLine));
    if (made.rule < 0 || made.step < 1) return out;
    const Production& rule = g.rules.productions[size_t(made.rule)];
    const auto& before = record.steps[size_t(made.step - 1)];
    const auto& origins = record.origins[size_t(made.step)];
    if (!before || !origins) return out;
    const std::uint32_t parent = origins->parent.data()[made.index];
    std::vector<std::size_t> left, right;
    // Kept by the derivation (L-Py's rules are Python), or found again from the rule.
    const ContextMatches* kept = size_t(made.step) < record.contexts.size() ? record.contexts[size_t(made.step)].get() : nullptr;
    if (kept) {
        if (!kept->find(parent, left, right)) return out;
    } else {
        StepRewriter rewriter(g, g.rules);
        if (!rule.hasContext() || !rewriter.contextOf(*before, parent, rule, left, right)) return out;
    }
    const std::vector<std::uint64_t> beforeCheckpoints = checkpointsOf(*before, g.alphabet);
    auto text = [&](std::size_t j) { return moduleAt(*before, g.alphabet, beforeCheckpoints, j) + " (" + std::to_string(j) + ")"; };
    std::string context = "context matched in step " + std::to_string(made.step - 1) + ": ";
    for (std::size_t j : left) context += text(j) + " ";
    context += "< [" + text(parent) + "] >";
    for (std::size_t j : right) context += " " + text(j);
    out.push_back(context);
    return out;
}

}  // namespace

std::vector<std::string> describeModule(const DerivationRecord& record, int step, std::uint32_t module) {
    if (step < 0 || size_t(step) >= record.steps.size() || !record.steps[size_t(step)] || module >= record.steps[size_t(step)]->size())
        return {};
    return describe(record, step, module, checkpointsOf(*record.steps[size_t(step)], record.grammar->alphabet));
}

void inspectorSection(App& app) {
    auto plant = app.state.plant();
    if (!plant || !plant->grammar) {
        ImGui::TextWrapped("The inspector shows the derivation of a grammar.");
        return;
    }
    if (!app.state.picking() || !plant->pick) {
        ImGui::TextWrapped("The inspector reads where every module came from, which the derivation keeps once asked.");
        if (!app.state.picking() && ImGui::Button("Inspect the derivation")) app.state.setPicking(true);
        return;
    }
    const PickData& pick = *plant->pick;
    const DerivationRecord& record = pick.record;
    const Grammar& g = *record.grammar;
    const int last = std::min(pick.step, int(record.steps.size()) - 1);
    App::Inspector& in = app.inspector;
    if (in.step < 0 || in.step > last) in.step = last;
    if (ImGui::TreeNode("modules per step")) {
        for (int k = 0; k <= last; ++k)
            if (record.steps[size_t(k)]) ImGui::Text("step %2d: %s modules", k, withThousands(record.steps[size_t(k)]->size()).c_str());
        ImGui::TreePop();
    }
    ImGui::SliderInt("step##inspect", &in.step, 0, last);
    const auto& string = record.steps[size_t(in.step)];
    if (!string) return;
    const std::uint64_t n = string->size();
    // What the view needs of this step, made once: parameter checkpoints and each module's rule.
    if (in.of != plant || in.cachedStep != in.step) {
        in.of = plant;
        in.cachedStep = in.step;
        in.checkpoints = checkpointsOf(*string, g.alphabet);
        in.describedChoice = -1;
        in.made = madeBy(record, in.step);
        in.first = std::min<std::uint64_t>(in.first, n ? n - 1 : 0);
    }
    // Search by module name: the next one after the chosen module.
    ImGui::SetNextItemWidth(120);
    ImGui::InputText("##find", in.query, sizeof in.query);
    ImGui::SameLine();
    if (ImGui::Button("find next") && in.query[0]) {
        std::uint64_t from = in.chosen >= 0 ? std::uint64_t(in.chosen) + 1 : 0;
        in.found = false;
        std::vector<char> named(g.alphabet.size(), 0);  // the symbols of that name, any arity
        for (size_t k = 0; k < named.size(); ++k) named[k] = g.alphabet[SymbolId(k)].name == in.query;
        for (std::uint64_t k = 0; k < n; ++k) {
            const std::uint64_t i = (from + k) % n;
            if (named[string->symbols.data()[i]]) {
                in.chosen = std::int64_t(i);
                in.first = i >= 8 ? i - 8 : 0;
                in.found = true;
                break;
            }
        }
    }
    if (in.query[0] && !in.found) {
        ImGui::SameLine();
        ImGui::TextDisabled("(none)");
    }
    std::uint64_t first = in.first;
    const std::uint64_t step = 64, big = kRows;
    ImGui::SetNextItemWidth(160);
    if (ImGui::InputScalar("from module", ImGuiDataType_U64, &first, &step, &big)) in.first = std::min(first, n ? n - 1 : 0);
    ImGui::TextDisabled("%s modules; colour: the rule that made each (grey: the axiom's)", withThousands(n).c_str());
    ImGui::BeginChild("##string", ImVec2(-1, ImGui::GetTextLineHeightWithSpacing() * 12), true);
    const std::uint64_t end = std::min(n, in.first + kRows);
    for (std::uint64_t i = in.first; i < end; ++i) {
        const std::int32_t rule = i < in.made.size() ? in.made[size_t(i)] : -1;
        ImGui::PushStyleColor(ImGuiCol_Text, ruleColour(rule));
        char label[160];
        std::snprintf(label, sizeof label, "%10llu  %s", static_cast<unsigned long long>(i), moduleAt(*string, g.alphabet, in.checkpoints, i).c_str());
        if (ImGui::Selectable(label, in.chosen == std::int64_t(i))) {
            in.chosen = std::int64_t(i);
            if (in.step == pick.step) app.selectModule(std::uint32_t(i));  // the drawn step: pick it in 3D
        }
        ImGui::PopStyleColor();
    }
    ImGui::EndChild();
    if (in.chosen < 0 || std::uint64_t(in.chosen) >= n) return;
    // The chosen module: its rule, where it came from, and the context that matched (worked
    // out once per choice: the step before may be millions of modules).
    if (in.describedChoice != in.chosen) {
        in.description = describe(record, in.step, std::uint32_t(in.chosen), in.checkpoints);
        in.describedChoice = in.chosen;
    }
    for (const std::string& line : in.description) ImGui::TextWrapped("%s", line.c_str());
}

}  // namespace sprout::viewer
