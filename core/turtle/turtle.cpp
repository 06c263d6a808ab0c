// The string turtle: interprets a module string one module at a time (see turtle_impl.hpp
// for the files the turtle is made of), and the entry points: a string, or the derivation
// tree the derivation hands over (core/derive/draw.cpp chooses).
#include "core/base/bounded.hpp"
#include "core/turtle/turtle_impl.hpp"

namespace sprout {

bool drawsSegment(const std::string& name) {
    using turtle_impl::Act;
    const Act a = turtle_impl::actionOf(name);
    return a == Act::Draw || a == Act::DrawNoVertex || a == Act::LineTo || a == Act::OLineTo || a == Act::LineRel || a == Act::OLineRel;
}

namespace turtle_impl {

Turtle::Turtle(const Grammar& g, const TurtleOptions& o, Geometry& out)
    : m_g(g), m_opt(o), m_out(out), m_segments(out.cylinders), m_rng(Rng::forStream(o.seed, 0x7077e)) {
    const auto& st = g.settings;
    m_actions.resize(g.alphabet.size());
    m_arity.resize(g.alphabet.size());
    for (size_t s = 0; s < g.alphabet.size(); ++s) {
        m_arity[s] = g.alphabet[SymbolId(s)].arity;
        m_actions[s] = actionOf(g.alphabet[SymbolId(s)].name);
        if (g.dialect == "cpfg") {  // cpfg's @ modules (blackbox.c), not Lparser's extensions
            const std::string& name = g.alphabet[SymbolId(s)].name;
            if (name == "@L") m_actions[s] = Act::CpfgLabel;
            else if (name == "@T" || name == "@A" || name == "@W") m_actions[s] = Act::None;
            else if (name == "@D") m_actions[s] = Act::ScaleSet;
            else if (name == "@Di") m_actions[s] = Act::ScaleMul;
            else if (name == "@Dd") m_actions[s] = Act::ScaleDiv;
            else if (name == "@Gr") m_actions[s] = Act::RadiusTangents;
            else if (name == "@Ts") m_actions[s] = Act::ElasticSet;
            else if (name == "@Ti") m_actions[s] = Act::ElasticInc;
            else if (name == "@Td") m_actions[s] = Act::ElasticDec;
            else if (name == "@PS") m_actions[s] = Act::PatchStart;
            else if (name == "@PC") m_actions[s] = Act::PatchPoint;
            else if (name == "@PD") m_actions[s] = Act::PatchDraw;
            else if (name == "@Tx") m_actions[s] = Act::TextureSet;
            m_scaled |= m_actions[s] == Act::ScaleSet || m_actions[s] == Act::ScaleMul || m_actions[s] == Act::ScaleDiv;
        }
        if (st.bracePaths && m_arity[s] > 0) {
            // A surface is kept by a quoted name (`}('leaf')`, `@Ge(8, 'leaf')`); a number there
            // (`}(0)`, the end of a path) keeps nothing, as in that tool (0 is no name in JavaScript).
            const std::uint32_t named = g.alphabet[SymbolId(s)].nameArgs;
            if (m_actions[s] == Act::PolyBegin) m_actions[s] = Act::CurveStart;
            else if (m_actions[s] == Act::PolyEnd && (named & 1)) m_actions[s] = Act::PolyEndSave;
            else if (m_actions[s] == Act::CurveEnd && (named & 2)) m_actions[s] = Act::CurveEndKeep;
            else if (g.alphabet[SymbolId(s)].name == "~") m_actions[s] = Act::InsertSaved;
        }
        if (st.bracePaths) {
            const std::string& name = g.alphabet[SymbolId(s)].name;
            if (name == "@Cs" || name == "@Ds") m_actions[s] = Act::ContourStart;
            else if (name == "@Ce" || name == "@De") m_actions[s] = Act::ContourEnd;
            else if (name == "@#") m_actions[s] = Act::ContourUse;
        }
        // cpfg's @#(id): the contour `contour: id FILE` names (core/language/vlab/) for the tubes to come.
        if (g.curves && g.alphabet[SymbolId(s)].name == "@#") m_actions[s] = Act::ContourUse;
        if (g.curves && g.alphabet[SymbolId(s)].name == "@!") m_actions[s] = Act::ContourSides;
        m_colourModules |= m_actions[s] == Act::ColourNext || m_actions[s] == Act::ColourPrev;
        m_hasCurves |= m_actions[s] == Act::CurveStart || m_actions[s] == Act::Section || m_actions[s] == Act::ContourUse;
        if (auto f = g.surfaceFiles.find(g.alphabet[SymbolId(s)].name); f != g.surfaceFiles.end()) {
            m_actions[s] = Act::SurfaceFile;
            m_surfaceFiles.resize(g.alphabet.size(), nullptr);
            m_surfaceFiles[s] = f->second.get();
        }
    }
    const auto& strings = g.alphabet.strings();
    for (size_t k = 0; k < strings.size(); ++k)
        if (strings[k].empty()) m_emptyName = double(k);  // `}('')`: no name, a polygon drawn
    m_gradient = st.gradient == Toggle::On || (st.gradient == Toggle::Auto && !m_colourModules);
    m_autoWidth = st.width <= 0;
    m_angle = toFloat(st.angle.mean) * kPi / 180.0f;
    cosSinDegrees(std::isfinite(st.angle.mean) ? st.angle.mean : 0.0, m_cos, m_sin);
    m_angleSigma = toFloat(st.angle.sigma) * kPi / 180.0f;
    m_stepSigma = toFloat(st.step.sigma);
    m_polygonEdgesDrawn = st.polygonEdgesDrawn;
    m_tropism = glm::vec3(toFloat(st.tropism[0]), toFloat(st.tropism[1]), toFloat(st.tropism[2]));
    if (glm::length(m_tropism) > 0) m_tropism = glm::normalize(m_tropism);
    m_tropismE = toFloat(st.tropismStrength);
    m_widthFactor = toFloat(st.widthFactor);
    m_branchLength = toFloat(st.branchLength);
    // Automatic widths thin each branch order, as real stems do (da Vinci's rule keeps
    // the total cross-section roughly constant at a fork).
    m_branchWidth = m_autoWidth && st.branchWidth == 1 ? 0.75f : toFloat(st.branchWidth);
    m_palette = st.palette;
    if (m_palette.empty()) m_palette.assign(std::begin(kDefaultPalette), std::end(kDefaultPalette));
    for (const Settings::MaterialEntry& e : st.materials) {  // `material:` lines, over the palette
        if (size_t(e.index) >= m_palette.size()) m_palette.resize(size_t(e.index) + 1, m_palette.back());
        m_palette[size_t(e.index)] = e.rgba;
    }
    if (m_palette.size() > 32767) m_palette.resize(32767);  // the state keeps the index in 16 bits
    for (const auto& [index, path] : st.textures) {  // each image once in the drawing
        if (index < 0 || size_t(index) >= m_palette.size() || path.empty()) continue;
        if (m_paletteTexture.size() <= size_t(index)) m_paletteTexture.resize(size_t(index) + 1, 0);
        m_paletteTexture[size_t(index)] = out.textureId(path);
    }
    for (const Settings::ViewTexture& v : st.viewTextures) m_viewTexture.push_back(out.textureId(v.file));  // cpfg's, by @Tx(n)
    m_texturing = !m_paletteTexture.empty() || !m_viewTexture.empty();
    m_colourStep = st.colourIncrement;
    m_widthSteps = st.widthIncrement.has_value();
    m_widthStep = toFloat(st.widthIncrement.value_or(0));
    // Colour by branch order: bark at the trunk, approaching the tip colour with each
    // order (t = 1 - 0.55^order), so no pass is needed to find the deepest order first.
    float t = 0;
    for (int o = 0; o < kOrderColours; ++o, t = 1 - (1 - t) * 0.55f)
        m_byOrder[o] = lerpColour(st.barkColour, st.tipColour, t);
    m_state.length = toFloat(st.step.mean * std::pow(st.stepScale, o.derivationSteps));
    m_cpfg = g.dialect == "cpfg";
    m_scaled = m_cpfg && (m_scaled || st.initialScale != 1);
    m_invStep = m_state.length != 0 && std::isfinite(m_state.length) ? 1.0f / m_state.length : 1.0f;
    m_scaleMultiplier = toFloat(st.scaleMultiplier);
    m_moves = m_cpfg && !st.movements.empty();
    for (size_t k = 0; k < st.movements.size() && k < m_elastic.size(); ++k) m_elastic[k] = toFloat(st.movements[k].elasticity);
    if (m_scaled) m_state.length *= toFloat(st.initialScale);
    m_state.width = m_autoWidth ? 1.0f : toFloat(st.width);
    m_min = m_max = m_state.pos;
    if (st.initialColour >= 0) {  // cpfg's initial color: a palette index from the start
        m_state.colour = std::int16_t(st.initialColour % int(m_palette.size()));
        m_gradient = false;
    }
    m_state.stemColour = stemColour(m_state);
    // Runs of F can be batched when nothing changes from one segment to the next.
    m_plainRuns = m_stepSigma <= 0 && m_tropismE == 0 && !m_moves && !(o.ages && o.growStep >= 0) && !m_texturing;
}

// Strings without parameters (most D0L plants) take a loop with no parameter walk.
void Turtle::run(const ModuleString& s) {
    // Strings without parameters (most D0L plants) take a loop with no parameter walk.
    if (s.params.empty()) runLoop<false>(s);
    else runLoop<true>(s);
    finish();
}

template <bool Parametric>
void Turtle::runLoop(const ModuleString& s) {
    const SymbolId* sym = s.symbols.data();
    const double* par = s.params.data();
    const size_t N = s.size();
    const Act* actions = m_actions.data();
    const std::uint8_t* arities = m_arity.data();
    // The state lives in a local for the loop so that the compiler keeps it in registers.
    State t = m_state;
    for (size_t i = 0; i < N; ++i) {
        const SymbolId id = sym[i];
        const double* p = nullptr;
        int arity = 0;
        if constexpr (Parametric) {
            arity = arities[id];
            p = par;
            par += arity;
        }
        const Act act = actions[id];
        if (act == Act::None) continue;
        if (act == Act::SurfaceFile) {  // a cpfg .s surface: its mesh comes from the symbol
            if constexpr (Parametric) {
                if (arity && !finite(p, arity)) continue;
            }
            m_surfaceModule = i;
            placeSurfaceFile(t, id, arity ? p : nullptr);
            continue;
        }
        if (act == Act::Draw && !arity && m_plainRuns && m_polygons.empty() && t.curve < 0) {
            // A run of plain F (F -> FF makes long ones): collinear segments in a tight loop.
            size_t j = i + 1;
            while (j < N && sym[j] == id) ++j;
            if (j - i > 1) {
                segmentRun(t, j - i, i);
                i = j - 1;
                continue;
            }
        }
        if constexpr (Parametric) {
            // NaN or infinity: skip, never draw garbage. A query module still reports its frame:
            // its parameters are answers to be written, whatever they hold now.
            if (arity && act != Act::Query && !finite(p, arity)) continue;
        }
        apply(t, act, arity ? p : nullptr, i, arity);
    }
    m_state = t;
    m_seg->finish();
}

}  // namespace turtle_impl

using namespace turtle_impl;

std::uint32_t defaultPaletteColour(int index) { return kDefaultPalette[((index % 16) + 16) % 16]; }

TurtleStats drawTree(const DerivationTree& tree, const Grammar& g, const TurtleOptions& options, Geometry& out) {
    out.clear();
    Turtle turtle(g, options, out);
    return turtle.runTree(tree.successors, tree.axiom, tree.n);
}

void drawString(const ModuleString& s, const Grammar& g, const TurtleOptions& options, Geometry& out) {
    out.clear();
    Turtle(g, options, out).run(s);
}

bool treeDrawable(const Grammar& g, const TurtleOptions& options) {
    Geometry unused;
    return Turtle(g, options, unused).treeApplicable();
}

}  // namespace sprout
