// The panel's Grammar section (the editor, its problems, the derivation's progress) and its
// "Why this branch?" section (the picked module, the rule that made it and its ancestors).
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "app/viewer/window/app.hpp"
#include "app/viewer/window/editor.hpp"
#include "app/viewer/window/panel_sections.hpp"

namespace sprout::viewer::detail {
namespace {

// ImGui's built-in font has ASCII only: show the messages' dashes and quotes that way.
std::string ascii(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s.compare(i, 3, "\xE2\x80\x94") == 0) {
            out += "--";
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

// Byte offset of (line, col) in `text`, columns counted in characters.
int offsetOf(const std::string& text, int line, int col) {
    size_t pos = 0;
    for (int l = 1; l < line && pos < text.size(); ++l) {
        size_t nl = text.find('\n', pos);
        if (nl == std::string::npos) return int(text.size());
        pos = nl + 1;
    }
    for (int c = 1; c < col && pos < text.size() && text[pos] != '\n'; ++c) {
        ++pos;
        while (pos < text.size() && (static_cast<unsigned char>(text[pos]) & 0xC0) == 0x80) ++pos;
    }
    return int(pos);
}

// Words the editor completes: settings, functions, and the grammar's longer module names.
std::vector<std::string> completionsFor(App& app) {
    static const char* fixed[] = {"angle:", "axiom:", "iterations:", "step:", "width:", "seed:", "tropism:", "palette:",
                                  "gradient:", "view:", "define:", "module:", "ignore:", "consider:", "environment:",
                                  "branch_scale:", "step_scale:", "sphere", "ellipsoid", "cylinder", "obstacle", "ground",
                                  "light", "attraction", "influence", "sin", "cos", "tan", "sqrt", "floor", "ceil", "min", "max",
                                  "ran", "nran", "random", "trunc", "fabs", "exp", "log", "pow", "atan2", "Lsystem:",
                                  "derivation length:", "Axiom:", "decomposition", "homomorphism", "endlsystem",
                                  "maximum depth:", "#define", "#include"};
    std::vector<std::string> out(std::begin(fixed), std::end(fixed));
    if (auto plant = app.state.plant(); plant && plant->grammar)
        for (size_t k = 0; k < plant->grammar->alphabet.size(); ++k) {
            const std::string& name = plant->grammar->alphabet[SymbolId(k)].name;
            if (name.size() >= 3 && std::isalpha(static_cast<unsigned char>(name[0]))) out.push_back(name);
        }
    return out;
}

}  // namespace

// Trust before code runs (app/viewer/state/trust.hpp): an L-Py model from outside shows its text
// and what it imports, and runs its Python only once the user says so.
static void trustBar(App& app) {
    if (!app.state.pythonBlocked()) return;
    const bool asking = app.state.pythonQuestion();
    ImGui::PushStyleColor(ImGuiCol_Text, kWarning);
    ImGui::TextWrapped("%s", asking ? "This L-Py model is a Python program. Sprout runs its Python only if you trust where it came from."
                                    : "Python not run: you chose not to trust this model. Its text is shown as it is.");
    ImGui::PopStyleColor();
    std::string imports;
    for (const PythonImport& i : app.state.imports()) {
        if (!imports.empty()) imports += ", ";
        imports += i.module + " (line " + std::to_string(i.line) + ")";
    }
    ImGui::TextWrapped("It imports: %s", imports.empty() ? "nothing" : imports.c_str());
    if (ImGui::Button("Trust and run")) app.state.answerTrust(true);
    if (asking) {
        ImGui::SameLine();
        if (ImGui::Button("Don't run")) app.state.answerTrust(false);
    }
    ImGui::Separator();
}

void grammarSection(App& app) {
    // The editor follows the text the rest of the viewer changes (sliders, a file opened).
    const std::string document = app.state.title() + "|" + app.state.path().string();
    // Another file or preset is a new document (a new undo history); Save as keeps the text.
    const bool newDocument = document != app.editorDocument && app.state.text() != app.editor.text();
    app.editorDocument = document;
    app.editor.sync(app.state.text(), newDocument, app.state.textGesture());
    if (app.jumpTo >= 0) {  // a clicked message or rule: the cursor goes there
        const editor::Pos p = app.editor.model().posOf(std::size_t(app.jumpTo));
        app.editor.gotoLineCol(p.line + 1, p.col + 1);
        app.jumpTo = -1;
    }
    std::vector<editor::Marker> markers;
    if (auto latest = app.state.latest())
        for (const auto& d : latest->diagnostics) markers.push_back({d.line, d.col, d.severity == Severity::Error, ascii(d.message)});
    const float h = std::max(160.0f, ImGui::GetTextLineHeight() * 16);
    FileKind kind = app.state.kind();
    if (kind == FileKind::Png) kind = FileKind::Lsys;
    app.editor.setBandLine(app.highlightLine);
    if (app.completionsOf != app.state.plant() || app.completions.empty()) {
        app.completions = completionsFor(app);
        app.completionsOf = app.state.plant();
    }
    trustBar(app);
    if (app.editor.draw("grammar", h, kind, markers, app.completions)) app.state.setText(app.editor.text());
    auto latest = app.state.latest();
    if (latest) {
        // Each problem at its line:col; a click puts the editor's cursor there.
        for (const auto& d : latest->diagnostics) {
            ImGui::PushStyleColor(ImGuiCol_Text, d.severity == Severity::Error ? kError : kWarning);
            char label[64];
            std::snprintf(label, sizeof label, "line %d, col %d##%d_%d", d.line, d.col, d.line, d.col);
            if (ImGui::SmallButton(label)) {
                app.jumpTo = offsetOf(app.state.text(), d.line, d.col);
            }
            ImGui::SameLine();
            ImGui::TextWrapped("%s%s", d.severity == Severity::Warning ? "warning: " : "", ascii(d.message).c_str());
            ImGui::PopStyleColor();
        }
        if (hasErrors(latest->diagnostics) && app.state.plant())
        {
            ImGui::PushStyleColor(ImGuiCol_Text, kDim);
            ImGui::TextWrapped("(the last good plant stays on screen until the text is fixed)");
            ImGui::PopStyleColor();
        }
        if (!latest->message.empty() && !latest->cancelled) {
            ImGui::PushStyleColor(ImGuiCol_Text, kError);
            ImGui::TextWrapped("%s", latest->message.c_str());
            ImGui::PopStyleColor();
        }
    }
    if (latest && latest->grammar) {
        // How the text was read (a pasted grammar: which notation, which settings it gave).
        const Grammar& g = *latest->grammar;
        const FileKind k = app.state.kind();
        const std::string dialect = k == FileKind::Lpy        ? "L-Py"
                                    : k == FileKind::Lparser  ? "Lparser"
                                    : k == FileKind::Fractint ? "Fractint"
                                                              : g.dialect;
        ImGui::PushStyleColor(ImGuiCol_Text, kDim);
        if (ImGui::TreeNode("readas", "read as %s", dialect.c_str())) {
            for (const auto& line : settingsReadLines(g)) ImGui::TextUnformatted(ascii(line).c_str());
            ImGui::TreePop();
        }
        ImGui::PopStyleColor();
    }
    const Worker& w = app.state.worker();
    if (w.busy()) {
        char label[64];
        std::snprintf(label, sizeof label, "deriving step %d", w.progressStep());
        ImGui::ProgressBar(w.progress(), ImVec2(-90, 0), label);
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) app.state.worker().cancel();
    } else {
        // The line keeps its height when no derivation runs, so that the sections below stay
        // where they are as derivations start and end: while a curve's point is dragged they
        // do so every few frames, and the editor's canvas moved under the mouse.
        ImGui::AlignTextToFramePadding();
        if (latest && !latest->cancelled && latest->deriveMs > 0) ImGui::TextColored(kDim, "derived in %.0f ms", latest->deriveMs);
        else ImGui::TextUnformatted("");
    }
}

namespace {

// The text of one line of the grammar (1-based), trimmed.
std::string lineText(const std::string& text, int line) {
    size_t pos = 0;
    for (int l = 1; l < line && pos != std::string::npos; ++l) {
        pos = text.find('\n', pos);
        if (pos != std::string::npos) ++pos;
    }
    if (pos == std::string::npos || pos >= text.size()) return "";
    std::string out = text.substr(pos, text.find('\n', pos) - pos);
    while (!out.empty() && (out.back() == '\r' || out.back() == ' ')) out.pop_back();
    return out;
}

}  // namespace

// Which rule made this branch: the picked module, its rule and ancestors; the rule under the
// editor's cursor, and how much it made.
void whySection(App& app) {
    auto plant = app.state.plant();
    if (!plant || !plant->geometry) return;
    if (plant->forest) {  // a forest: which plant, which species
        if (!app.selection || app.selection->forestPlant < 0 || app.selection->plant != plant) {
            ImGui::TextWrapped("Click a plant in the view to see which one it is and its species.");
            return;
        }
        const ForestPlant& f = (*plant->forest)[size_t(app.selection->forestPlant)];
        ImGui::Text("plant %d of %zu: %s%s", app.selection->forestPlant + 1, plant->forest->size(), f.species.c_str(),
                    f.grass ? " (grass)" : "");
        ImGui::Text("at (%.1f, %.1f), turned %.0f deg; %s %u of its %u", double(f.at.x), double(f.at.z), double(f.yaw),
                    app.selection->surface ? "surface" : "segment", app.selection->module,
                    app.selection->surface ? f.surfaces : f.segments);
        ImGui::TextDisabled("open the species (Presets or File) to see which rule made it");
        return;
    }
    if (!plant->grammar) return;
    if (!app.state.picking()) {
        ImGui::TextWrapped("Click a stem or leaf in the view to see which module drew it and which rule made it.");
        if (ImGui::Button("Start picking")) app.state.setPicking(true);
        return;
    }
    const std::string& text = app.state.text();
    // The rule under the cursor: everything it made lights up (when the cursor comes to it).
    if (const int line = app.editor.model().cursor().line + 1; app.followCursor && line != app.cursorLine) {
        app.cursorLine = line;
        bool isRule = false;
        for (const Production& p : plant->grammar->rules.productions) isRule |= p.line == line;
        for (const Production& p : plant->grammar->decomposition.productions) isRule |= p.line == line;
        if (isRule) app.setHighlightLine(line);
    }
    ImGui::Checkbox("highlight what the rule under the cursor made", &app.followCursor);
    if (app.highlightLine > 0) {
        ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.25f, 1), "line %d made %zu stems and leaves:", app.highlightLine, app.highlightCount);
        ImGui::TextWrapped("%s", ascii(lineText(text, app.highlightLine)).c_str());
        if (ImGui::SmallButton("clear highlight")) app.setHighlightLine(0);
    }
    ImGui::Separator();
    if (!app.selection) {
        ImGui::TextWrapped("Click a stem or leaf in the view.");
        return;
    }
    const App::Selection& sel = *app.selection;
    const PickData& pick = *sel.plant->pick;
    const Grammar& g = *pick.record.grammar;
    const auto& drawn = pick.record.steps[size_t(pick.step)];
    if (pick.homomorphism) {
        ImGui::TextWrapped("%s, module %u of the string the interpretation rules drew (their modules have no lineage).",
                           sel.surface ? "a leaf" : "a stem", sel.module);
        return;
    }
    if (!drawn || sel.module >= drawn->size()) return;
    ImGui::Text("%s %s, module %u of step %d", sel.surface ? "leaf / surface" : "stem", sel.text.c_str(),
                sel.module, pick.step);
    for (size_t k = 0; k < sel.links.size(); ++k) {
        const LineageLink& l = sel.links[k];
        ImGui::PushID(int(k));
        const std::string name = g.alphabet[l.symbol].name;
        if (l.ruleLine > 0) {
            // ABOP's label when the rule has one: "p2, line 5".
            const Production* rule = ruleOf(g, l.rule);
            const std::string label = rule && !rule->label.empty() ? ascii(rule->label) + ", " : "";
            if (ImGui::SmallButton((label + "line " + std::to_string(l.ruleLine)).c_str())) {
                app.jumpTo = offsetOf(text, l.ruleLine, 1);
                app.setHighlightLine(l.ruleLine);
            }
            ImGui::SameLine();
            ImGui::TextWrapped("%s%s made at step %d by: %s", k ? "<- " : "", name.c_str(), l.step, ascii(lineText(text, l.ruleLine)).c_str());
        } else {
            ImGui::TextWrapped("%s%s, module %u of the axiom", k ? "<- " : "", name.c_str(), l.index);
        }
        ImGui::PopID();
    }
}

}  // namespace sprout::viewer::detail
