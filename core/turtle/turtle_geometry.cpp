// The geometry the turtle emits beyond stems: polygons ({ . }, @c discs), predefined
// surfaces and spheres, cpfg's point and heading commands, generalized cylinders, and the
// finish of a drawing (automatic widths, bounds, planar curves).
//
// Index of this file:
//   [SECTION] Generalized cylinders and their contours
//   [SECTION] cpfg's point and heading commands
//   [SECTION] Polygons and kept surfaces
//   [SECTION] Surfaces, the finish, bounds
#include <algorithm>

#include "core/base/bounded.hpp"
#include "core/turtle/turtle_impl.hpp"

namespace sprout {
namespace turtle_impl {

// [SECTION] Generalized cylinders and their contours

// Generalized cylinders: @Gs starts one at the turtle, @Gc(n) adds a control point (and
// makes n the pieces of each following span), @Ge(n) adds the last one, @Gt(s) sets the
// tangents' length in chords. Every F in between is a control point too.
void Turtle::curveCommand(State& t, Act act, const double* p, int arity) {
    if (act == Act::CurveStart) {
        if (m_curves.size() >= 32767) return;  // the state keeps the index in 16 bits
        m_curves.emplace_back();
        m_curves.back().curve.left = toGlm(t.L);
        const size_t fixed = m_g.settings.sections.size();
        if (t.section >= 0 && size_t(t.section) < fixed) {
            const std::vector<float>& xy = m_g.settings.sections[size_t(t.section)];
            for (size_t k = 0; k + 1 < xy.size(); k += 2) m_curves.back().curve.section.emplace_back(xy[k], xy[k + 1]);
        } else if (t.section >= 0 && size_t(t.section) - fixed < m_contours.size()) {
            m_curves.back().curve.section = m_contours[size_t(t.section) - fixed];
        }
        m_curves.back().start = {toGlm(t.pos), toGlm(t.H), toGlm(t.L), toGlm(up(t))};
        if (const std::uint32_t image = textureOf(t); image && !m_level) {  // its image, as the turtle has it now
            GeneralizedCylinder& tube = m_curves.back().curve;
            const TexTransform& x = m_texTransforms[size_t(t.texture)];
            tube.image = image;
            tube.texScale = x.scale, tube.texTranslation = x.translation, tube.texCentre = x.centre, tube.texAngle = x.angle;
            if (x.along > 0) tube.texScale.y *= x.along / std::max(t.width, 1e-6f);  // cpfg's proportions
        }
        t.curve = std::int16_t(m_curves.size() - 1);
        t.lastSegment = -1;
        curvePoint(t, 1);
        return;
    }
    if (t.curve < 0) return;
    auto& c = m_curves[size_t(t.curve)];
    const int n = p ? int(std::clamp(*p, 1.0, 64.0)) : c.subdivisions;
    if (act == Act::CurveTangent) {
        c.curve.tangentScale = p ? float(std::clamp(*p, 0.0, 10.0)) : 1.0f;
        return;
    }
    if (act == Act::CurvePoint) c.subdivisions = n;
    curvePoint(t, n);
    if (act == Act::CurveEnd || act == Act::CurveEndKeep) {
        // L-system Explorer's @Ge(n, 'name'): the tube is kept by that name, not drawn.
        if (act == Act::CurveEndKeep && p && arity >= 2 && p[1] != m_emptyName) keepTube(size_t(t.curve), p[1]);
        t.curve = -1;
    }
}

// cpfg's turtle carries its generalized cylinder into a branch (the state is copied at '['):
// the branch's tube goes on from the parent's last control point, with its contour and
// tangents, and ends at the branch's @Ge (Horneophyton's forking stems).
void Turtle::forkCurve(State& t, std::int16_t parent) {
    if (m_curves.size() >= 32767) return;
    OpenCurve fork;
    const OpenCurve& from = m_curves[size_t(parent)];
    fork.subdivisions = from.subdivisions;
    fork.start = from.start;
    fork.curve.left = toGlm(t.L);
    fork.curve.tangentScale = from.curve.tangentScale;
    fork.curve.section = from.curve.section;
    if (!from.curve.points.empty()) fork.curve.points.push_back(from.curve.points.back());
    m_curves.push_back(std::move(fork));
    t.curve = std::int16_t(m_curves.size() - 1);
}

void Turtle::keepTube(std::size_t curve, double name) {
    if (m_saved.size() >= 4096 && !m_saved.count(name)) return;
    OpenCurve& c = m_curves[curve];
    Mesh world;
    appendTube(c.curve, 1.0f, world);
    c.curve.points.clear();  // drawn where it is put, not here
    keepMesh(std::move(world), c.start, name);
}

// A contour's points are where the turtle stood at each '.', in the x y plane (the tool's
// convention: contours are drawn there, usually after @H or @R), in units of the tube's radius.
void Turtle::contourCommand(State& t, Act act, const double* p) {
    if (act == Act::ContourStart) {
        m_capturing = true;
        m_contour.clear();
        return;
    }
    if (act == Act::ContourEnd) {
        if (!m_capturing) return;
        m_capturing = false;
        const double id = p ? p[0] : 0;
        if (m_contour.size() < 2 || !std::isfinite(id)) return;
        const size_t fixed = m_g.settings.sections.size();
        auto it = m_contourIds.find(id);
        if (it == m_contourIds.end()) {
            if (fixed + m_contours.size() >= 32767) return;
            it = m_contourIds.emplace(id, std::int16_t(fixed + m_contours.size())).first;
            m_contours.emplace_back();
        }
        std::vector<glm::vec2>& section = m_contours[size_t(it->second) - fixed];
        section.clear();
        for (const glm::vec2& q : m_contour) section.push_back(2.0f * q);  // the tool's size is a diameter
        return;
    }
    if (act == Act::ContourSides) {  // cpfg: @! alone is 8 sides, fewer than 3 are 3
        t.sides = std::int16_t(p ? std::clamp(saturate<int>(p[0]), 3, 1024) : 8);
        return;
    }
    // cpfg's @#(id) with the view file's contour id: sampled at the turtle's sides (@!), else
    // at `contour sides:`, once for each count.
    if (m_g.curves && p && m_g.curves->contours.count(saturate<int>(p[0]))) {
        const int id = saturate<int>(p[0]), sides = t.sides > 0 ? t.sides : m_g.curves->contourSides;
        auto found = m_fileContours.find({id, sides});
        if (found == m_fileContours.end()) {
            const size_t fixed = m_g.settings.sections.size();
            if (fixed + m_contours.size() >= 32767) return;
            found = m_fileContours.emplace(std::pair(id, sides), std::int16_t(fixed + m_contours.size())).first;
            auto& section = m_contours.emplace_back();
            for (const std::array<float, 2>& q : m_g.curves->section(id, sides)) section.emplace_back(q[0], q[1]);
        }
        t.section = found->second;
        return;
    }
    // @#(id): that contour for the paths to come; an id never defined (the tool's 'default'): round.
    auto it = p ? m_contourIds.find(p[0]) : m_contourIds.end();
    t.section = it == m_contourIds.end() ? std::int16_t(-1) : it->second;
}

void Turtle::curvePoint(const State& t, int subdivisions) {
    auto& c = m_curves[size_t(t.curve)];
    const glm::vec3 p = toGlm(t.pos);
    if (!c.curve.points.empty() && glm::length(c.curve.points.back().position - p) < 1e-7f) {
        c.curve.points.back().radius = t.width * 0.5f;  // the same place: update, do not repeat
        c.curve.points.back().subdivisions = subdivisions;
        return;
    }
    c.curve.points.push_back({p, glm::normalize(toGlm(t.H)), t.width * 0.5f, t.stemColour, subdivisions, m_radiusIn,
                              m_radiusOut, m_scaleRadius});
}

// [SECTION] cpfg's point and heading commands

// cpfg's @M(x,y,z), @R(hx,hy,hz[,ux,uy,uz]) and @c(r): rare, so out of the hot switch.
void Turtle::cpfgCommand(State& t, Act act, const double* p, int arity) {
    if (act == Act::Pinpoint || act == Act::PinpointRel) {
        if (!p || arity < 3) return;
        glm::vec3 to{float(p[0]), float(p[1]), float(p[2])};
        if (act == Act::Pinpoint) to -= toGlm(t.pos);
        tendTo(t, to);
        return;
    }
    if (act == Act::MoveTo || act == Act::MoveRel) {
        if (!p || arity < 3) return;
        const v4 by{float(p[0]), float(p[1]), float(p[2]), 0};
        t.pos = act == Act::MoveRel ? t.pos + by : by;
        t.pos[3] = 0;
        t.lastSegment = -1;  // the next segment starts a new stem there
        addBound(t.pos);
        if (!m_polygons.empty()) vertex(t);
        return;
    }
    if (act == Act::SetHeading) {
        if (!p || arity < 3) return;
        glm::vec3 h{float(p[0]), float(p[1]), float(p[2])};
        if (!(glm::length(h) > 1e-12f)) return;
        h = glm::normalize(h);
        glm::vec3 l = toGlm(t.L);
        if (arity >= 6) {  // with an up vector: L = U x H
            glm::vec3 u{float(p[3]), float(p[4]), float(p[5])};
            l = glm::cross(u, h);
        } else {           // keep the left vector as near as it was
            l -= glm::dot(l, h) * h;
        }
        if (!(glm::length(l) > 1e-6f)) {
            l = glm::cross(std::fabs(h.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0), h);
        }
        t.H = fromGlm(h);
        t.L = fromGlm(glm::normalize(l));
        return;
    }
    // @c(r): a disc of radius r across the heading, as a 24-sided polygon (cpfg's @c(d): of
    // diameter d, times the turtle's scale).
    const float r = p ? (m_cpfg ? float(p[0]) * scaleOf(t) * 0.5f : float(p[0])) : t.width * 0.5f;
    if (!(r > 0)) return;
    const glm::vec3 c = toGlm(t.pos), l = toGlm(t.L), u = toGlm(up(t));
    std::vector<glm::vec3> pts;
    for (int k = 0; k < 24; ++k) {
        const float a = 2 * kPi * float(k) / 24;
        pts.push_back(c + r * (std::cos(a) * l + std::sin(a) * u));
        addBound(fromGlm(pts.back()));
    }
    emitPolygon(t, pts);
}

namespace {
// [SECTION] Polygons and kept surfaces

// Two outline points are one when they are apart by no more than float rounding can put
// them at their distance from the origin: a few hundred ulps, relative. An absolute 1e-6 was
// one ulp at 10 units, so whether an outline's closing point was dropped depended on how its
// frames were multiplied, and the tree and the string turtle drew different polygons.
constexpr float kPointRounding = 2e-5f;  // relative to 1 + the largest coordinate
float roundingAt(const glm::vec3& m) { return kPointRounding * (1 + std::max({m.x, m.y, m.z})); }
bool samePoint(const glm::vec3& a, const glm::vec3& b) {
    return !(glm::length(a - b) > roundingAt(glm::max(glm::abs(a), glm::abs(b))));
}
}  // namespace

void Turtle::vertex(const State& t) {
    auto& poly = m_polygons.back();
    glm::vec3 p = toGlm(t.pos);
    if (poly.empty() || !samePoint(poly.back(), p)) poly.push_back(p);
}

void Turtle::emitPolygon(const State& t, std::vector<glm::vec3>& pts, Mesh* into, const Frame* at) {
    if (pts.size() > 1 && samePoint(pts.front(), pts.back())) pts.pop_back();
    if (pts.size() < 3) return;
    Mesh& m = into ? *into : m_out.polygons;
    // Newell's normal: robust for concave and slightly non-planar outlines.
    glm::vec3 n(0), far(0);
    float perimeter = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        const glm::vec3& a = pts[i];
        const glm::vec3& b = pts[(i + 1) % pts.size()];
        n += glm::vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        perimeter += glm::length(b - a);
        far = glm::max(far, glm::abs(a));
    }
    // Twice the area. An outline no wider than its points' rounding (twice the area over the
    // perimeter) is a line and is not drawn: its area is rounding noise, zero or not
    // depending on how its frames were multiplied (an absolute 1e-12 let the tree and the
    // string turtle fill different collinear leaves, a fuzz find now in fuzz/regressions/derive).
    float len = glm::length(n);
    if (!(len > perimeter * roundingAt(far))) return;
    n /= len;
    std::uint32_t base = std::uint32_t(m.positions.size());
    std::uint32_t col = t.colour >= 0 ? colour(t.colour) : colour(kLeafColour);
    for (const auto& p : pts) {
        m.positions.push_back(p);
        m.normals.push_back(n);
        m.colours.push_back(col);
        if (!into) addBound(fromGlm(p));
    }
    triangulatePolygon(pts, base, m.indices);
    if (!into && m_texturing && !m_level) polygonTexcoords(t, at ? *at : Frame{toGlm(t.pos), toGlm(t.H), toGlm(t.L), toGlm(up(t))}, base);
}

// L-system Explorer's `{ ... }(name)`: the polygon is kept, not drawn, in the frame the
// turtle had at its '{'; `~(name, scale)` draws it in the turtle's frame, scaled.
void Turtle::keepPolygon(const State& t, std::vector<glm::vec3>& pts, const Frame& at, double name) {
    if (m_saved.size() >= 4096 && !m_saved.count(name)) return;
    Mesh world;
    emitPolygon(t, pts, &world);
    keepMesh(std::move(world), at, name);
}

// A kept surface is stored in the frame `at`: x along its L, y along H, z along U.
void Turtle::keepMesh(Mesh&& world, const Frame& at, double name) {
    Mesh& kept = m_saved[name];
    kept.clear();
    auto local = [&](const glm::vec3& v) { return glm::vec3(glm::dot(v, at.l), glm::dot(v, at.h), glm::dot(v, at.u)); };
    for (size_t k = 0; k < world.positions.size(); ++k) {
        kept.positions.push_back(local(world.positions[k] - at.origin));
        kept.normals.push_back(local(world.normals[k]));
    }
    kept.colours = std::move(world.colours);
    kept.indices = std::move(world.indices);
}

void Turtle::insertKept(const State& t, const double* p, int arity) {
    if (!p) return;
    auto it = m_saved.find(*p);
    if (it == m_saved.end()) return;  // none of that name kept (yet): nothing to draw
    const Mesh& kept = it->second;
    const float scale = arity >= 2 && std::isfinite(p[1]) ? float(std::clamp(p[1], -1e6, 1e6)) : 1.0f;
    const glm::vec3 o = toGlm(t.pos), h = toGlm(t.H), l = toGlm(t.L), u = toGlm(up(t));
    Mesh& m = m_out.polygons;
    if (m.positions.size() + kept.positions.size() > (std::size_t(1) << 31)) return;
    const std::uint32_t base = std::uint32_t(m.positions.size());
    const std::uint32_t col = t.colour >= 0 ? colour(t.colour) : 0;
    for (size_t k = 0; k < kept.positions.size(); ++k) {
        const glm::vec3& a = kept.positions[k];
        const glm::vec3& n = kept.normals[k];
        m.positions.push_back(o + scale * (a.x * l + a.y * h + a.z * u));
        m.normals.push_back(n.x * l + n.y * h + n.z * u);
        m.colours.push_back(t.colour >= 0 ? col : kept.colours[k]);
        addBound(fromGlm(m.positions.back()));
    }
    for (std::uint32_t i : kept.indices) m.indices.push_back(base + i);
}

// [SECTION] Surfaces, the finish, bounds

void Turtle::surface(const State& t, Act act, const double* p, float grow) {
    SurfaceInstance s;
    s.position = toGlm(t.pos);
    s.heading = toGlm(t.H);
    s.up = toGlm(up(t));
    if (act == Act::Sphere) {
        s.kind = SurfaceKind::Sphere;
        s.size = p ? float(*p) : t.width;  // radius
        if (m_cpfg) s.size = (p ? s.size * scaleOf(t) : s.size) * 0.5f;  // cpfg's @O(d): a diameter
    } else {
        s.kind = act == Act::Leaf ? SurfaceKind::Leaf : SurfaceKind::Petal;
        s.size = p ? float(*p) : t.length;
    }
    s.colour = surfaceColour(t, s.kind);
    s.size *= grow;
    if (!(s.size > 0)) return;
    if (m_level) {  // a block being built: resolved when placed
        s.colour = t.colour >= 0 ? std::uint32_t(t.colour) : kInheritColour;
        m_scratch[size_t(m_level) - 1].surfaces.push_back(s);  // bounded when placed
        return;
    }
    m_out.surfaces.push_back(s);
    if (m_opt.surfaceModules) m_opt.surfaceModules->push_back(std::uint32_t(m_surfaceModule));
    if (m_texturing) noteTexturedSurface(t);
    addBound(t.pos);
    addBound(t.pos + t.H * s.size);
}

// L-Py's texture transforms: a new transform from the turtle's, with the module's change.
void Turtle::textureCommand(State& t, Act act, const double* p, int arity) {
    TexTransform x = m_texTransforms[size_t(t.texture)];
    if (act == Act::TextureSet) {  // cpfg's @Tx(n), from 1; none (or out of range): no texture
        const double n = p && arity >= 1 && finite(p, 1) ? std::trunc(p[0]) : 0;
        const bool valid = n >= 1 && n <= double(m_viewTexture.size());
        x.image = valid ? std::int32_t(m_viewTexture[size_t(n) - 1]) : 0;
        x.perSurface = valid && m_g.settings.viewTextures[size_t(n) - 1].perSurface;
        if (valid) {
            const Settings::ViewTexture& v = m_g.settings.viewTextures[size_t(n) - 1];
            x.along = v.aspect / (kPi * (v.ratio > 0 ? v.ratio : 1.0f));
        }
    } else if (!p || arity < 1 || !finite(p, arity)) {
        return;
    }
    auto at = [&](int k, float otherwise) { return k < arity ? float(p[k]) : otherwise; };
    switch (act) {
        case Act::TextureSet: break;
        case Act::TextureScale: x.scale = {at(0, 1), at(1, at(0, 1))}; break;
        case Act::TextureUScale: x.scale.x = at(0, 1); break;
        case Act::TextureVScale: x.scale.y = at(0, 1); break;
        case Act::TextureTranslation: x.translation = {at(0, 0), at(1, at(0, 0))}; break;
        case Act::TextureRotation:
            x.angle = at(0, 0) * kPi / 180;
            x.centre = {at(1, 0.5f), at(2, at(1, 0.5f))};
            break;
        default:  // TextureTransformation(su, sv, tu, tv, angle, cu, cv)
            x.scale = {at(0, 1), at(1, 1)};
            x.translation = {at(2, 0), at(3, 0)};
            x.angle = at(4, 0) * kPi / 180;
            x.centre = {at(5, 0.5f), at(6, 0.5f)};
            break;
    }
    if (m_texTransforms.size() >= 32767) m_texTransforms.resize(1);  // the state keeps it in 16 bits: start over
    m_texTransforms.push_back(x);
    t.texture = std::int16_t(m_texTransforms.size() - 1);
}

void Turtle::finish() {
    Geometry& out = m_out;
    for (const auto& [index, shine] : m_g.settings.shines)  // what shines, by the colour drawn
        if (index >= 0 && size_t(index) < m_palette.size() && !shine.plain()) out.shines.push_back({m_palette[size_t(index)], shine});
    out.bounds.empty = false;
    out.bounds.min = toGlm(m_min);
    out.bounds.max = toGlm(m_max);
    // Automatic width: stems in proportion to the plant, 1/80 of its size at the base.
    float k = 1.0f;
    if (m_autoWidth && !m_absoluteWidths) {
        glm::vec3 size = out.bounds.size();
        float extent = std::max({size.x, size.y, size.z});
        if (extent > 0) k = extent / 80.0f;
        for (auto& s : out.surfaces)
            if (s.kind == SurfaceKind::Sphere) s.size *= k;
    }
    if (k != 1.0f) {
        for (auto& c : out.cylinders) {
            c.startRadius *= k;
            c.endRadius *= k;
        }
    }
    if (m_opt.meshes)
        for (const auto& c : m_curves) appendTube(c.curve, k, out.polygons);
    // A planar curve: every point in the z = 0 plane and no branches or surfaces.
    const float tol = 1e-4f * (1 + glm::length(out.bounds.size()));
    bool flat = std::fabs(out.bounds.min.z) < tol && std::fabs(out.bounds.max.z) < tol;
    auto view = m_g.settings.view;
    out.planarCurve = flat && view != ViewHint::Solid &&
                      (view == ViewHint::Flat || (!m_usedBrackets && out.surfaces.empty()));
    if (m_texturing) drawTextured();
}

// A cpfg surface file at the turtle: its frame (heading, left, up) mapped onto the turtle's,
// scaled by the module's parameter and the step length, coloured like a leaf.
void Turtle::placeSurfaceFile(const State& t, SymbolId id, const double* p) {
    if (!m_opt.meshes) return;
    const SurfaceFile& f = *m_surfaceFiles[id];
    const float scale = (p ? float(*p) : 1.0f) * t.length;
    const glm::vec3 pos = toGlm(t.pos), h = toGlm(t.H), l = toGlm(t.L), u = toGlm(up(t));
    auto turned = [&](const glm::vec3& q) { return q.x * h + q.y * l + q.z * u; };  // the surface's frame in the turtle's
    Mesh& m = m_out.polygons;
    const std::uint32_t base = std::uint32_t(m.positions.size());
    const std::uint32_t col = surfaceColour(t, SurfaceKind::Leaf);
    for (size_t k = 0; k < f.positions.size(); ++k) {
        m.positions.push_back(pos + scale * turned(f.positions[k]));
        m.normals.push_back(turned(f.normals[k]));
        // (A block's colours stay palette steps until it is placed: a surface's own are not.)
        m.colours.push_back(!m_level && k < f.colours.size() && f.colours[k] ? f.colours[k] : col);
        addBound(fromGlm(m.positions.back()));
    }
    const TexTransform& tx = m_texTransforms[size_t(t.texture)];
    const auto& uvs = tx.perSurface && f.surfaceUvs.size() == f.positions.size() ? f.surfaceUvs : f.uvs;
    std::uint32_t image = textureOf(t);
    if (!f.texture.empty() && !m_level) image = m_out.textureId(f.texture);  // the surface's own (its Shape's appearance)
    if (image && !m_level && uvs.size() == f.positions.size()) {
        // Its texture coordinates, through the turtle's texture transform.
        m.texcoords.resize(base);
        for (const auto& uv : uvs) {
            const glm::vec2 q = tx(glm::vec2(uv[0], uv[1]));
            m.texcoords.push_back({q.x, q.y, image});
        }
    }
    for (std::uint32_t i : f.indices) m.indices.push_back(base + i);
    for (size_t k = 0; k + 1 < f.lines.size(); k += 2) {
        const v4 a = fromGlm(pos + scale * turned(f.lines[k])), b = fromGlm(pos + scale * turned(f.lines[k + 1]));
        addBound(a);
        addBound(b);
        stem(t, a, b, m_surfaceModule);
    }
}

}  // namespace turtle_impl

void Bounds::add(const glm::vec3& p) {
    if (empty) {
        min = max = p;
        empty = false;
        return;
    }
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Bounds::add(const Bounds& b) {
    if (b.empty) return;
    add(b.min);
    add(b.max);
}

std::uint32_t Geometry::textureId(const std::string& path) {
    const auto found = std::find(textures.begin(), textures.end(), path);
    if (found == textures.end()) return textures.push_back(path), std::uint32_t(textures.size());
    return std::uint32_t(found - textures.begin()) + 1;
}

std::uint64_t Geometry::bytes() const {
    std::uint64_t b = std::uint64_t(cylinders.size()) * sizeof(CylinderInstance) + std::uint64_t(surfaces.size()) * sizeof(SurfaceInstance);
    b += (polygons.positions.size() + polygons.normals.size()) * sizeof(glm::vec3) +
         (polygons.colours.size() + polygons.indices.size()) * sizeof(std::uint32_t) + polygons.texcoords.size() * sizeof(TexCoord);
    for (const Label& l : labels) b += sizeof(Label) + l.text.size();
    return b;
}

void Geometry::clear() {
    cylinders.clear();
    surfaces.clear();
    polygons.clear();
    labels.clear();
    shines.clear();
    textures.clear();
    bounds = {};
    backdrop = {};
    backdropFirst = backdropCount = 0;
    planarCurve = false;
}


void placeGeometry(const Geometry& g, float yaw, const glm::vec3& at, Geometry& out) {
    const float c = std::cos(yaw * 3.14159265f / 180), s = std::sin(yaw * 3.14159265f / 180);
    auto turn = [&](const glm::vec3& p) { return glm::vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z); };
    auto move = [&](const glm::vec3& p) { return turn(p) + at; };
    for (const auto& cyl : g.cylinders) {
        CylinderInstance x = cyl;
        x.start = move(cyl.start);
        x.end = move(cyl.end);
        out.cylinders.push_back(x);
        out.bounds.add(x.start);
        out.bounds.add(x.end);
    }
    for (const auto& sf : g.surfaces) {
        SurfaceInstance x = sf;
        x.position = move(sf.position);
        x.heading = turn(sf.heading);
        x.up = turn(sf.up);
        out.surfaces.push_back(x);
        out.bounds.add(x.position);
    }
    const std::uint32_t base = std::uint32_t(out.polygons.positions.size());
    for (size_t i = 0; i < g.polygons.positions.size(); ++i) {
        out.polygons.positions.push_back(move(g.polygons.positions[i]));
        out.polygons.normals.push_back(turn(g.polygons.normals[i]));
        out.polygons.colours.push_back(g.polygons.colours[i]);
        out.bounds.add(out.polygons.positions.back());
    }
    for (auto i : g.polygons.indices) out.polygons.indices.push_back(base + i);
    out.shines.insert(out.shines.end(), g.shines.begin(), g.shines.end());
    if (!g.polygons.texcoords.empty()) {  // its images among the drawing's, each once
        std::vector<std::uint32_t> id(g.textures.size() + 1, 0);
        for (size_t k = 0; k < g.textures.size(); ++k) id[k + 1] = out.textureId(g.textures[k]);
        out.polygons.texcoords.resize(base);
        for (TexCoord c : g.polygons.texcoords) {
            c.texture = c.texture < id.size() ? id[c.texture] : 0;
            out.polygons.texcoords.push_back(c);
        }
    }
}

}  // namespace sprout
