// The tree-drawing optimizer: a D0L string that is step n of its grammar is drawn from its
// derivation tree. Every subtree S(s, d) (symbol s after d steps) that occurs at least twice,
// is of a useful size and holds only modules whose drawing does not depend on where the
// turtle is, is drawn once as a block in the identity frame and then placed wherever it
// occurs by transforming its segments (see the README's Performance section).
#include "core/turtle/turtle_impl.hpp"

namespace sprout::turtle_impl {

// Draws step n of a D0L grammar from its derivation tree instead of its string (which
// must be that step: see drawTree). A subtree that occurs more than once is drawn once
// in a frame of its own, as a block, and then placed wherever it occurs by transforming
// its segments: no dispatch per module, and the string is never read.
TurtleStats Turtle::runTree(const SuccessorTable& tree, const ModuleString& axiom, int n) {
    m_tree = &tree;
    m_alpha = m_actions.size();
    setLeaves();
    // Without a subtree to place, walking the tree module by module is slower than the string.
    if (!planBlocks(axiom, n)) return {};
    m_work.clear();
    State t = m_state;
    for (SymbolId s : axiom.symbols) walk(s, n, t);
    m_state = t;
    m_seg->finish();
    finish();
    m_work.trim();
    return {true, m_blocks.size()};
}

// Which (s, d) become blocks: those that occur at least twice in the tree, are of a
// useful size, contain only block actions and close every bracket they open.
// Returns how many there are.
size_t Turtle::planBlocks(const ModuleString& axiom, int n) {
    const size_t A = m_alpha, D = size_t(n) + 1;
    static constexpr std::uint64_t kSat = 1ull << 62;
    auto sat = [](std::uint64_t a) { return std::min(a, kSat); };
    std::vector<std::uint64_t> modules(D * A), occurs(D * A, 0);
    std::vector<std::uint8_t> ok(D * A);
    std::vector<std::int64_t> net(D * A), low(D * A);  // bracket depth change, lowest prefix
    for (size_t d = 0; d < D; ++d) {
        for (size_t s = 0; s < A; ++s) {
            const size_t k = d * A + s;
            const SymbolId id = SymbolId(s);
            if (d == 0 || m_tree->identity(id)) {
                std::int64_t depth = 0, lowest = 0;
                bool good = true;
                for (std::uint32_t i = m_leafStart[s]; i < m_leafStart[s + 1]; ++i) {
                    const Act a = m_leafActs[i];
                    good = good && blockAction(a);
                    depth += a == Act::Push ? 1 : a == Act::Pop ? -1 : 0;
                    lowest = std::min(lowest, depth);
                }
                modules[k] = 1;
                ok[k] = good;
                net[k] = depth;
                low[k] = lowest;
                continue;
            }
            std::uint64_t m = 0;
            bool good = true;
            std::int64_t depth = 0, lowest = 0;
            for (const SymbolId* c = m_tree->successorBegin(id); c != m_tree->successorEnd(id); ++c) {
                const size_t kc = (d - 1) * A + *c;
                m = sat(m + modules[kc]);
                good = good && ok[kc];
                lowest = std::min(lowest, depth + low[kc]);
                depth = std::clamp<std::int64_t>(depth + net[kc], -std::int64_t(kSat), std::int64_t(kSat));
            }
            modules[k] = m;
            ok[k] = good;
            net[k] = depth;
            low[k] = lowest;
        }
    }
    for (SymbolId s : axiom.symbols) occurs[size_t(n) * A + s] = sat(occurs[size_t(n) * A + s] + 1);
    for (size_t d = D - 1; d > 0; --d) {
        for (size_t s = 0; s < A; ++s) {
            const std::uint64_t o = occurs[d * A + s];
            if (!o || m_tree->identity(SymbolId(s))) continue;
            for (const SymbolId* c = m_tree->successorBegin(SymbolId(s)); c != m_tree->successorEnd(SymbolId(s)); ++c)
                occurs[(d - 1) * A + *c] = sat(occurs[(d - 1) * A + *c] + o);
        }
    }
    m_blockState.assign(D * A, BlockState::No);
    m_blockIndex.assign(D * A, 0);
    size_t candidates = 0;
    for (size_t d = 1; d < D; ++d) {
        for (size_t s = 0; s < A; ++s) {
            const size_t k = d * A + s;
            if (occurs[k] >= 2 && ok[k] && net[k] == 0 && low[k] >= 0 && !m_tree->identity(SymbolId(s)) &&
                modules[k] >= kMinBlockModules && modules[k] <= kMaxBlockModules)
                m_blockState[k] = BlockState::Unbuilt, ++candidates;
        }
    }
    return candidates;
}

// What a symbol of the derived string draws: its own action, or the actions of its
// interpretation rule's successor (cpfg's homomorphism, applied once at the leaves).
void Turtle::setLeaves() {
    m_leafStart.assign(m_alpha + 1, 0);
    m_leafActs.clear();
    for (size_t s = 0; s < m_alpha; ++s) {
        m_leafStart[s] = std::uint32_t(m_leafActs.size());
        const auto* list = s < m_g.interpretation.bySymbol.size() ? &m_g.interpretation.bySymbol[s] : nullptr;
        if (list && !list->empty()) {
            for (SymbolId c : m_g.interpretation.productions[list->front()].successor.symbols)
                if (m_actions[c] != Act::None) m_leafActs.push_back(m_actions[c]);
        } else if (m_actions[s] != Act::None) {
            m_leafActs.push_back(m_actions[s]);
        }
    }
    m_leafStart[m_alpha] = std::uint32_t(m_leafActs.size());
}

// The modules a symbol stands for at the tree's leaves, applied one by one. Out of line: walk()
// recurses once per derivation step, and with the turtle's step inlined into it, its frame was
// 5 KB (under AddressSanitizer), 1,000 steps deep past the 8 MB stack.
void Turtle::walkLeaves(SymbolId s, State& t) {
    for (std::uint32_t i = m_leafStart[s]; i < m_leafStart[s + 1]; ++i) {
        const Act act = m_leafActs[i];
        if (m_level) {
            // Inside a block being built: the segment before the block is not ours to taper.
            if ((act == Act::WidthDec || act == Act::WidthInc || act == Act::ScaleWidth) && t.lastSegment == kEntrySegment) {
                m_abort = true;
                return;
            }
            apply(t, act, nullptr, 0);
            if (act == Act::Move || act == Act::MoveNoVertex) m_scratch[m_level - 1].points.push_back(t.pos);
            continue;
        }
        apply(t, act, nullptr, 0);
    }
}

void Turtle::walk(SymbolId s, int d, State& t) {
    if (d == 0 || m_tree->identity(s)) {
        walkLeaves(s, t);
        return;
    }
    const size_t k = size_t(d) * m_alpha + s;
    if (m_blockState[k] != BlockState::No && t.angleScale == 1.0f && m_polygons.empty()) {
        if (m_blockState[k] == BlockState::Unbuilt) build(s, d);
        if (m_blockState[k] == BlockState::Built) {
            const Block& b = m_blocks[m_blockIndex[k]];
            // A surface's size follows the turtle's length or width: not negative ones.
            if (!b.surfaces || (t.length > 0 && t.width > 0)) {
                place(b, t);
                return;
            }
        }
    }
    for (const SymbolId* c = m_tree->successorBegin(s); c != m_tree->successorEnd(s) && !m_abort; ++c) walk(*c, d - 1, t);
}

void Turtle::build(SymbolId s, int d) {
    const size_t k = size_t(d) * m_alpha + s;
    m_blockState[k] = BlockState::No;  // unless it completes
    if (m_blockSegs.size() > kMaxBlockSegments) return;
    if (m_scratch.size() <= size_t(m_level)) m_scratch.emplace_back();
    TreeScratch& scratch = m_scratch[size_t(m_level)];
    scratch.segments.clear();
    scratch.surfaces.clear();
    scratch.points.clear();
    SegmentWriter& local = scratch.writer;
    SegmentWriter* outer = m_seg;
    const v4 outerMin = m_min, outerMax = m_max;
    const size_t stackBase = m_stack.size();
    const bool outerBrackets = m_usedBrackets;
    m_seg = &local;
    m_usedBrackets = false;
    ++m_level;
    State t;
    t.lastSegment = kEntrySegment;
    t.stemColour = stemColour(t);
    for (const SymbolId* c = m_tree->successorBegin(s); c != m_tree->successorEnd(s) && !m_abort; ++c) walk(*c, d - 1, t);
    local.finish();
    --m_level;
    m_seg = outer;
    m_min = outerMin;
    m_max = outerMax;
    const bool brackets = m_usedBrackets;
    m_usedBrackets = outerBrackets;
    if (m_abort || m_stack.size() != stackBase || t.order != 0) {
        m_abort = false;
        m_stack.resizeUninitialized(stackBase);
        return;  // walked instead, in the caller's frame
    }
    Block b;
    b.first = std::uint32_t(m_blockSegs.size());
    b.count = std::uint32_t(scratch.segments.size());
    b.firstPoint = std::uint32_t(m_blockPoints.size());
    b.points = std::uint32_t(scratch.points.size());
    b.pos = t.pos;
    b.H = t.H;
    b.L = t.L;
    b.length = t.length;
    b.width = t.width;
    b.lastSegment = t.lastSegment;
    b.colour = t.colour;
    b.brackets = brackets;
    b.colours = false;
    for (const auto& c : scratch.segments) b.colours |= c.colour != kInheritColour;
    b.firstSurface = std::uint32_t(m_blockSurfs.size());
    b.surfaces = std::uint32_t(scratch.surfaces.size());
    m_blockSurfs.append(scratch.surfaces.data(), scratch.surfaces.size());
    m_blockSegs.append(scratch.segments.data(), scratch.segments.size());
    m_blockPoints.insert(m_blockPoints.end(), scratch.points.begin(), scratch.points.end());
    m_blockIndex[k] = std::uint32_t(m_blocks.size());
    m_blocks.push_back(b);
    m_blockState[k] = BlockState::Built;
}

// Draws block b for turtle t and moves t to where the block leaves it.
void Turtle::place(const Block& b, State& t) {
    const v4 ax = -t.L, ay = t.H, az = up(t);  // the identity frame's x y z, turned
    const v4 sx = ax * t.length, sy = ay * t.length, sz = az * t.length;
    const v4 radius = v4{0, 0, 0, t.width};
    v4 origin = t.pos;
    origin[3] = 0;
    auto at = [&](v4 p) { return origin + sx * p[0] + sy * p[1] + sz * p[2] + p * radius; };
    // Colours: a segment that took no palette step has the turtle's colour (by branch order,
    // or its palette entry; inside a block being built, its step code); one that did is
    // that many steps from the turtle's palette entry.
    const bool byOrder = !m_level && t.colour < 0 && m_gradient;
    const std::uint32_t fixed = t.stemColour;
    const int order = t.order;
    const int palette = int(m_palette.size()), from = std::max<int>(t.colour, 0);
    auto stepped = [&](std::uint32_t code) {
        const int index = (from + int(code)) % palette;
        return m_level ? std::uint32_t(index) : m_palette[size_t(index)];
    };
    const std::size_t base = m_seg->count();
    const CylinderInstance* src = m_blockSegs.data() + b.first;
    const std::uint32_t count = b.count;
    v4 lo = m_min, hi = m_max;
    // Two copies of the loop: most blocks take no palette step, and the check costs there.
    auto segments = [&](auto colours) {
        v4 low = lo, high = hi;  // locals: in registers, not stored at every segment
        for (std::uint32_t i = 0; i < count; ++i) {
            v4 a, e;
            std::memcpy(&a, &src[i].start, 16);
            std::memcpy(&e, &src[i].end, 16);
            const v4 wa = at(a), we = at(e);
            CylinderInstance& c = m_seg->next();
            std::memcpy(&c.start, &wa, 16);
            std::memcpy(&c.end, &we, 16);
            const int o = std::min(order + src[i].order, 65535);
            c.order = std::uint16_t(o);
            c.colour = byOrder ? m_byOrder[std::min(o, kOrderColours - 1)] : fixed;
            if constexpr (decltype(colours)::value)
                if (src[i].colour != kInheritColour) c.colour = stepped(src[i].colour);
            c.step = 0;
            low = __builtin_ia32_minps(low, we);
            high = __builtin_ia32_maxps(high, we);
        }
        lo = low;
        hi = high;
    };
    if (b.colours) segments(std::true_type{});
    else segments(std::false_type{});
    m_min = lo;
    m_max = hi;
    for (std::uint32_t i = 0; i < b.surfaces; ++i) {
        SurfaceInstance s = m_blockSurfs[b.firstSurface + i];
        const v4 p = at(fromGlm(s.position)), h = fromGlm(s.heading), u = fromGlm(s.up);
        s.position = toGlm(p);
        s.heading = toGlm(ax * h[0] + ay * h[1] + az * h[2]);
        s.up = toGlm(ax * u[0] + ay * u[1] + az * u[2]);
        s.size *= s.kind == SurfaceKind::Sphere ? t.width : t.length;
        if (s.colour != kInheritColour) s.colour = stepped(s.colour);
        else if (m_level) s.colour = t.colour >= 0 ? std::uint32_t(t.colour) : kInheritColour;
        else s.colour = surfaceColour(t, s.kind);
        if (m_level) {
            m_scratch[size_t(m_level) - 1].surfaces.push_back(s);
            continue;
        }
        m_out.surfaces.push_back(s);
        addBound(p);
        addBound(p + fromGlm(s.heading) * s.size);
    }
    for (std::uint32_t i = 0; i < b.points; ++i) {
        v4 p = at(m_blockPoints[b.firstPoint + i]);
        p[3] = 0;
        if (m_level) m_scratch[size_t(m_level) - 1].points.push_back(p);
        else addBound(p);
    }
    t.pos = at(b.pos);
    t.pos[3] = 0;
    const v4 H = ax * b.H[0] + ay * b.H[1] + az * b.H[2];
    const v4 L = ax * b.L[0] + ay * b.L[1] + az * b.L[2];
    t.H = H;
    t.L = L;
    t.length *= b.length;
    t.width *= b.width;
    if (b.colour >= 0) {
        t.colour = std::int16_t((from + b.colour) % palette);
        t.stemColour = stemColour(t);
    }
    if (b.lastSegment >= 0) t.lastSegment = std::int32_t(base) + b.lastSegment;
    else if (b.lastSegment == -1) t.lastSegment = -1;
    m_usedBrackets |= b.brackets;
}

}  // namespace sprout::turtle_impl
