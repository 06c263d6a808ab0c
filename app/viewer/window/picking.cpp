// Picking in the viewer: a click in the 3D view finds the stem or leaf under it (core/pick),
// the module that drew it (recorded by the turtle) and, from the origins the derivation keeps,
// the rule that made it and its ancestors (core/provenance). The other way, a rule's line
// highlights every segment that rule made. The origins are only kept once picking is asked
// for: a plant nobody clicks costs nothing.
#include "app/render/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>

#include "app/viewer/window/app.hpp"
#include "core/turtle/pick.hpp"

namespace sprout::viewer {

bool App::pickAt(double x, double y) {
    auto plant = state.plant();
    if (!plant || !plant->geometry) return false;
    if (!plant->pick && !plant->forest) {  // the first click: the derivation must keep its origins
        selection.reset();
        state.setPicking(true);
        pendingPick = std::make_pair(x, y);
        return false;
    }
    pendingPick.reset();
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window, &fw, &fh);
    const float vw = float(std::max(1, fw - panelWidth)), vh = float(std::max(1, fh));
    const float nx = (float(x) - float(panelWidth)) / vw * 2 - 1, ny = 1 - float(y) / vh * 2;
    const float dist = std::max(camera.distance, 1e-3f);
    const glm::mat4 inverse = glm::inverse(camera.projection(vw / vh, dist * 1e-3f, dist * 100) * camera.view());
    const glm::vec4 a = inverse * glm::vec4(nx, ny, -1, 1), b = inverse * glm::vec4(nx, ny, 1, 1);
    const glm::vec3 origin = glm::vec3(a) / a.w, direction = glm::normalize(glm::vec3(b) / b.w - origin);
    // Three pixels of slack: a hairline stem can be clicked.
    const float pixel = camera.orthographic ? camera.orthoHeight / vh : 2 * std::tan(glm::radians(camera.fovY) / 2) / vh;
    auto hit = camera.orthographic ? pick(*plant->geometry, origin, direction, 0.0f, 3 * pixel)
                                   : pick(*plant->geometry, origin, direction, 3 * pixel);
    selection.reset();
    if (hit) {
        Selection s;
        s.plant = plant;
        s.surface = hit->kind == PickHit::Kind::Surface;
        s.instance = hit->index;
        if (plant->forest) {  // a forest: which plant, which species
            for (size_t k = 0; k < plant->forest->size(); ++k) {
                const ForestPlant& f = (*plant->forest)[k];
                const std::uint32_t first = s.surface ? f.firstSurface : f.firstSegment, count = s.surface ? f.surfaces : f.segments;
                if (hit->index >= first && hit->index < first + count) s.forestPlant = int(k), s.module = hit->index - first;
            }
        } else {
            const auto& map = s.surface ? plant->pick->surfaceModules : plant->pick->segmentModules;
            if (hit->index < map.size()) s = selectionOf(plant, map[hit->index], s.surface, hit->index);
        }
        selection = std::move(s);
        if (!selection->links.empty() && followCursor) setHighlightLine(selection->links[0].ruleLine);
    }
    highlightDirty = true;
    needsRedraw = true;
    return true;
}

std::string App::describeSelection() const {
    if (!selection) return "module=none";
    if (selection->forestPlant >= 0) {
        const ForestPlant& f = (*selection->plant->forest)[size_t(selection->forestPlant)];
        return "plant=" + std::to_string(selection->forestPlant + 1) + " species=" + f.species + (f.grass ? " (grass)" : "") +
               (selection->surface ? " surface=" : " segment=") + std::to_string(selection->module);
    }
    const Grammar& g = *selection->plant->pick->record.grammar;
    const auto& steps = selection->plant->pick->record.steps;
    const int drawn = selection->plant->pick->step;
    std::string name = "?";
    if (size_t(drawn) < steps.size() && steps[size_t(drawn)] && selection->module < steps[size_t(drawn)]->size())
        name = g.alphabet[steps[size_t(drawn)]->symbols.data()[selection->module]].name;
    std::string out = "module=" + name + " index=" + std::to_string(selection->module);
    if (!selection->links.empty()) {
        const LineageLink& l = selection->links[0];
        out += " step=" + std::to_string(l.step) + " rule_line=" + std::to_string(l.ruleLine);
        // ABOP's label of that rule, when it has one ("p2").
        if (const Production* rule = ruleOf(g, l.rule); rule && !rule->label.empty()) out += " rule_label=" + rule->label;
    }
    return out;
}

void App::setHighlightLine(int line) {
    if (line == highlightLine) return;
    highlightLine = line;
    highlightDirty = true;
    needsRedraw = true;
}

void App::updateHighlight() {
    highlightDirty = false;
    highlightOf = state.plant();
    Mesh mesh;
    highlightCount = 0;
    auto plant = state.plant();
    if (plant && plant->geometry && plant->pick && highlightLine > 0 && !plant->pick->homomorphism) {
        // Every module the rule on that line made, then every stem and leaf they drew.
        const Grammar& g = *plant->pick->record.grammar;
        const std::vector<std::int32_t> made = madeBy(plant->pick->record, plant->pick->step);
        auto hits = [&](std::int32_t rule) { return rule != -1 && ruleLine(g, rule) == highlightLine; };
        std::vector<std::uint32_t> segments, surfaces;
        for (std::uint32_t i = 0; i < plant->pick->segmentModules.size(); ++i) {
            const std::uint32_t m = plant->pick->segmentModules[i];
            if (m < made.size() && hits(made[m])) segments.push_back(i);
        }
        for (std::uint32_t i = 0; i < plant->pick->surfaceModules.size(); ++i) {
            const std::uint32_t m = plant->pick->surfaceModules[i];
            if (m < made.size() && hits(made[m])) surfaces.push_back(i);
        }
        highlightCount = segments.size() + surfaces.size();
        highlightMesh(*plant->geometry, segments, surfaces, 0xffb43cff, mesh);
    }
    if (selection && selection->plant == plant && plant && plant->geometry) {
        std::vector<std::uint32_t> one{selection->instance}, none;
        highlightMesh(*plant->geometry, selection->surface ? none : one, selection->surface ? one : none, 0xfff03cff, mesh);
    }
    renderer.setHighlight(mesh);
    needsRedraw = true;
}

App::Selection App::selectionOf(std::shared_ptr<const Result> plant, std::uint32_t module, bool surface,
                                std::uint32_t instance) const {
    Selection s;
    s.plant = plant;
    s.module = module;
    s.surface = surface;
    s.instance = instance;
    const PickData& pick = *plant->pick;
    if (!pick.homomorphism) s.links = lineage(pick.record, pick.step, module);
    const auto& drawn = pick.record.steps[size_t(pick.step)];
    if (drawn && module < drawn->size()) {  // its parameters follow those of the modules before it
        const Alphabet& alphabet = pick.record.grammar->alphabet;
        std::size_t p = 0;
        for (std::uint32_t i = 0; i < module; ++i) p += alphabet[drawn->symbols.data()[i]].arity;
        appendModule(s.text, alphabet[drawn->symbols.data()[module]], drawn->params.data() + p, &alphabet);
    }
    return s;
}

void App::selectModule(std::uint32_t index) {
    auto plant = state.plant();
    if (!plant || !plant->pick) return;
    bool surface = false, drawn = false;
    std::uint32_t instance = std::uint32_t(-1);  // drawing nothing: nothing is outlined
    for (std::uint32_t i = 0; i < plant->pick->segmentModules.size() && !drawn; ++i)
        if (plant->pick->segmentModules[i] == index) instance = i, drawn = true;
    for (std::uint32_t i = 0; i < plant->pick->surfaceModules.size() && !drawn; ++i)
        if (plant->pick->surfaceModules[i] == index) instance = i, surface = drawn = true;
    selection = selectionOf(plant, index, surface, instance);
    highlightDirty = true;
}

}  // namespace sprout::viewer
