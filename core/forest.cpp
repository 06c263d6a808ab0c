#include "core/forest.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include "core/file_kind.hpp"
#include "core/turtle.hpp"

namespace sprout {

bool isForestScene(std::string_view text) {
    std::istringstream in{std::string(text.substr(0, 4096))};
    std::string line;
    while (std::getline(in, line)) {
        size_t a = line.find_first_not_of(" \t");
        if (a == std::string::npos || line[a] == '#') continue;
        return line.compare(a, 6, "scene:") == 0 && line.find("forest") != std::string::npos;
    }
    return false;
}

ForestParseResult parseForest(std::string_view text) {
    ForestParseResult r;
    Forest f;
    std::istringstream in{std::string(text)};
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (size_t h = line.find('#'); h != std::string::npos) line.resize(h);
        std::istringstream words(line);
        std::string key;
        if (!(words >> key)) continue;
        auto bad = [&](const std::string& msg) { r.diagnostics.push_back({number, 1, msg, Severity::Error}); };
        if (key == "scene:") {
            std::string kind;
            words >> kind;
            if (kind != "forest") bad("only 'scene: forest' is known");
        } else if (key == "grid:") {
            if (!(words >> f.columns >> f.rows) || f.columns < 1 || f.rows < 1 || f.columns * f.rows > 10000)
                bad("expected 'grid: COLUMNS ROWS' with at most 10000 cells");
        } else if (key == "spacing:") {
            if (!(words >> f.spacing) || !(f.spacing > 0)) bad("expected a positive 'spacing:'");
        } else if (key == "seed:") {
            if (!(words >> f.seed)) bad("expected a whole number after 'seed:'");
        } else if (key == "species:") {
            Forest::Species s;
            s.line = number;
            if (!(words >> s.name >> s.share) || !(s.share > 0)) bad("expected 'species: NAME SHARE' with a positive share");
            else f.species.push_back(s);
        } else if (key == "grass:") {
            if (!(words >> f.grass >> f.grassPerCell) || f.grassPerCell < 0 || f.grassPerCell > 100)
                bad("expected 'grass: NAME PER_CELL' (0 to 100 per cell)");
        } else {
            bad("unknown scene setting '" + key + "'");
        }
    }
    if (f.species.empty() && r.diagnostics.empty()) r.diagnostics.push_back({1, 1, "a forest needs at least one 'species:'", Severity::Error});
    if (r.diagnostics.empty()) r.forest = std::move(f);
    return r;
}

namespace {

struct Species {
    std::shared_ptr<const Grammar> grammar;
};

// Appends `g` turned by `yaw` degrees about +Y and moved to `at`.
void place(const Geometry& g, float yaw, const glm::vec3& at, Geometry& out) {
    const float c = std::cos(yaw * 3.14159265f / 180), s = std::sin(yaw * 3.14159265f / 180);
    auto move = [&](const glm::vec3& p) { return glm::vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z) + at; };
    auto turn = [&](const glm::vec3& p) { return glm::vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z); };
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
    }
    for (auto i : g.polygons.indices) out.polygons.indices.push_back(base + i);
}

}  // namespace

bool buildForest(const Forest& f, const GrammarSource& source, Geometry& out, ForestStats& stats, std::string& error,
                 const DeriveLimits& limits) {
    out.clear();
    stats = {};
    std::map<std::string, std::shared_ptr<const Grammar>> grammars;
    auto load = [&](const std::string& name) -> std::shared_ptr<const Grammar> {
        if (auto it = grammars.find(name); it != grammars.end()) return it->second;
        auto text = source(name);
        if (!text) {
            error = "no preset or file named '" + name + "'";
            return nullptr;
        }
        ParseResult r = parseDetected(*text);  // a species may be a cpfg-family file
        if (!r.ok()) {
            error = name + ": " + formatDiagnostic(r.diagnostics.front(), name);
            return nullptr;
        }
        return grammars[name] = r.grammar;
    };
    double total = 0;
    for (const auto& s : f.species) {
        if (!load(s.name)) return false;
        total += s.share;
    }
    if (f.grassPerCell && !load(f.grass)) return false;

    Rng rng = Rng::forStream(f.seed, 0xF0E57);
    const float cell = float(f.spacing);
    std::vector<float> rowShift(std::size_t(f.rows)), columnShift(std::size_t(f.columns));
    for (auto& v : rowShift) v = float(rng.uniform() * 0.4 - 0.2) * cell;  // whole rows by up to 20%
    for (auto& v : columnShift) v = float(rng.uniform() * 0.4 - 0.2) * cell;
    Geometry plant;
    auto grow = [&](const std::shared_ptr<const Grammar>& g, std::uint64_t seed, float yaw, glm::vec3 at) {
        DeriveOptions o;
        o.seed = seed;  // each plant its own specimen
        o.limits = limits;
        Derivation d(g, o);
        const int n = g->settings.iterations;
        DeriveOutcome outcome = d.deriveTo(n);
        if (!outcome.ok()) {
            error = outcome.message;
            return false;
        }
        interpret(*d.step(n), *g, {n, seed, nullptr}, plant);
        place(plant, yaw, at, out);
        stats.segments += plant.cylinders.size();
        return true;
    };
    for (int r = 0; r < f.rows; ++r) {
        for (int c = 0; c < f.columns; ++c) {
            // Species by share, position jittered by up to 30% of the cell.
            double u = rng.uniform() * total;
            const Forest::Species* s = &f.species.back();
            for (const auto& sp : f.species) {
                if (u < sp.share) {
                    s = &sp;
                    break;
                }
                u -= sp.share;
            }
            float x = (float(c) - (f.columns - 1) / 2.0f) * cell + columnShift[std::size_t(c)] + float(rng.uniform() * 0.6 - 0.3) * cell;
            float z = (float(r) - (f.rows - 1) / 2.0f) * cell + rowShift[std::size_t(r)] + float(rng.uniform() * 0.6 - 0.3) * cell;
            float yaw = 0;
            do yaw = float(rng.normal(180, 60));
            while (yaw <= 0);
            if (!grow(grammars[s->name], rng.next(), yaw, {x, 0, z})) return false;
            ++stats.plants;
            for (int k = 0; k < f.grassPerCell; ++k) {
                float gx = x + float(rng.uniform() - 0.5) * cell, gz = z + float(rng.uniform() - 0.5) * cell;
                if (!grow(grammars[f.grass], rng.next(), float(rng.uniform() * 360), {gx, 0, gz})) return false;
                ++stats.grasses;
            }
        }
    }
    out.planarCurve = false;
    return true;
}

}  // namespace sprout
