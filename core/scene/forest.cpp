#include "core/scene/forest.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include "core/base/bounded.hpp"
#include "core/language/file_kind.hpp"
#include "core/turtle/turtle.hpp"

namespace sprout {

ForestParseResult parseForest(std::string_view text, const IncludeReader& include) {
    ForestParseResult r;
    Forest f;
    std::istringstream in{std::string(text)};
    std::string line;
    int number = 0;
    // The environment lines, each on its own line number in an otherwise empty grammar: the
    // grammar parser reads them as it does in a grammar, and its messages keep their line:col.
    std::string environmentText;
    bool hasEnvironment = false;
    while (std::getline(in, line)) {
        ++number;
        if (size_t h = line.find('#'); h != std::string::npos) line.resize(h);
        std::istringstream words(line);
        std::string key;
        if (!(words >> key)) {
            environmentText += '\n';
            continue;
        }
        if (key == "environment:") {
            environmentText += line + '\n';
            hasEnvironment = true;
            continue;
        }
        environmentText += '\n';
        auto bad = [&](const std::string& msg) { r.diagnostics.push_back({number, 1, msg, Severity::Error}); };
        if (key == "scene:") {
            std::string kind;
            words >> kind;
            if (kind != "forest") bad("only 'scene: forest' is known");
        } else if (key == "grid:") {
            if (!(words >> f.columns >> f.rows) || f.columns < 1 || f.rows < 1 ||
                std::int64_t(f.columns) * f.rows > 10000)
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
    if (hasEnvironment) {
        ParseOptions environmentOptions;
        environmentOptions.include = include;
        ParseResult e = parse(environmentText + "axiom: F\n", environmentOptions);
        for (const Diagnostic& d : e.diagnostics)
            if (d.severity == Severity::Error) r.diagnostics.push_back(d);
        if (e.grammar) f.environment = e.grammar->environment;
    }
    if (f.species.empty() && r.diagnostics.empty()) r.diagnostics.push_back({1, 1, "a forest needs at least one 'species:'", Severity::Error});
    if (r.diagnostics.empty()) r.forest = std::move(f);
    return r;
}

namespace {

// A plant that asks the shared environment, and where it stands.
struct SharingPlant {
    std::shared_ptr<const Grammar> grammar;
    std::uint64_t seed;
    float yaw;
    glm::vec3 at;
    std::string species;
};

// Grows the plants step by step together: after each step the forest's one environment
// answers every plant's ?E where it stands, seeing all of them.
bool growTogether(const Forest& f, const std::vector<SharingPlant>& plants, Geometry& out, ForestStats& stats, std::string& error,
                  const DeriveLimits& limits, std::vector<ForestPlant>* placed) {
    std::vector<std::unique_ptr<Derivation>> derivations;
    int steps = 0;
    for (const SharingPlant& p : plants) {
        DeriveOptions o;
        o.seed = p.seed;
        o.limits = limits;
        o.holdQueries = true;
        derivations.push_back(std::make_unique<Derivation>(p.grammar, o));
        steps = std::max(steps, p.grammar->settings.iterations);
    }
    // A plant that has reached its own n stays in the world, and its last step is answered
    // again with the others (its question is about the environment as it is now).
    auto answer = [&](int step) {
        std::vector<QueryTarget> targets;
        for (size_t i = 0; i < plants.size(); ++i) {
            const int k = std::min(step, plants[i].grammar->settings.iterations);
            targets.push_back({plants[i].grammar.get(), derivations[i]->unansweredStep(), k, plants[i].seed, plants[i].yaw,
                               glm::dvec3(plants[i].at)});
        }
        std::string why;
        if (answerQueriesTogether(f.environment, f.seed, targets, &why)) return true;
        error = "step " + std::to_string(step) + ": " + why;
        return false;
    };
    if (!answer(0)) return false;
    for (int k = 1; k <= steps; ++k) {
        for (size_t i = 0; i < plants.size(); ++i) {
            if (k > plants[i].grammar->settings.iterations) continue;
            DeriveOutcome o = derivations[i]->deriveTo(k);
            if (!o.ok()) {
                error = "plant " + std::to_string(i + 1) + " (" + plants[i].species + "): " + o.message;
                return false;
            }
        }
        // Their strings live together: one budget for all of them.
        std::uint64_t together = 0;
        for (size_t i = 0; i < plants.size(); ++i)
            together += derivations[i]->step(std::min(k, plants[i].grammar->settings.iterations))->bytes();
        if (together > limits.maxBytes) {
            error = "step " + std::to_string(k) + ": the strings of the " + std::to_string(plants.size()) +
                    " plants that share the environment take " + humanBytes(together) + ", over the memory budget of " +
                    humanBytes(limits.maxBytes) + "; lower their n, the grid or raise the budget (--max-memory)";
            return false;
        }
        if (!answer(k)) return false;
    }
    Geometry plant;
    for (size_t i = 0; i < plants.size(); ++i) {
        const int n = plants[i].grammar->settings.iterations;
        interpret(*derivations[i]->step(n), *plants[i].grammar, {n, plants[i].seed, nullptr}, plant);
        if (placed)
            placed->push_back({plants[i].species, plants[i].at, plants[i].yaw, false, std::uint32_t(out.cylinders.size()),
                               std::uint32_t(plant.cylinders.size()), std::uint32_t(out.surfaces.size()),
                               std::uint32_t(plant.surfaces.size())});
        placeGeometry(plant, plants[i].yaw, plants[i].at, out);
        stats.segments += plant.cylinders.size();
    }
    stats.sharing = int(plants.size());
    return true;
}

}  // namespace

bool buildForest(const Forest& f, const GrammarSource& source, Geometry& out, ForestStats& stats, std::string& error,
                 const DeriveLimits& limits, std::vector<ForestPlant>* placed) {
    if (placed) placed->clear();
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
    const float cell = toFloat(f.spacing);
    std::vector<float> rowShift(std::size_t(f.rows)), columnShift(std::size_t(f.columns));
    for (auto& v : rowShift) v = float(rng.uniform() * 0.4 - 0.2) * cell;  // whole rows by up to 20%
    for (auto& v : columnShift) v = float(rng.uniform() * 0.4 - 0.2) * cell;
    Geometry plant;
    // Plants that ask the shared environment: grown after the others, all together.
    std::vector<SharingPlant> sharing;
    auto grow = [&](const std::string& species, std::uint64_t seed, float yaw, glm::vec3 at, bool grass) {
        const std::shared_ptr<const Grammar>& g = grammars[species];
        if (!f.environment.empty() && g->hasQueries()) {
            sharing.push_back({g, seed, yaw, at, species});
            return true;
        }
        // The forest has one memory budget: a plant may take what the plants before it left.
        const std::uint64_t used = out.bytes();
        auto over = [&](const std::string& why) {
            error = "plant " + std::to_string(stats.plants + stats.grasses + 1) + " (" + species + "): " + why;
            if (used) error += "; the forest's plants before it take " + humanBytes(used) + " of its budget of " + humanBytes(limits.maxBytes);
            return false;
        };
        DeriveOptions o;
        o.seed = seed;  // each plant its own specimen
        o.limits = limits;
        o.limits.maxBytes = limits.maxBytes > used ? limits.maxBytes - used : 0;
        Derivation d(g, o);
        const int n = g->settings.iterations;
        DeriveOutcome outcome = d.deriveTo(n);
        if (outcome.ok()) outcome = checkDrawing(*d.step(n), *g, o.limits, n);
        if (!outcome.ok()) return over(outcome.message);
        interpret(*d.step(n), *g, {n, seed, nullptr}, plant);
        if (placed)
            placed->push_back({species, at, yaw, grass, std::uint32_t(out.cylinders.size()), std::uint32_t(plant.cylinders.size()),
                               std::uint32_t(out.surfaces.size()), std::uint32_t(plant.surfaces.size())});
        placeGeometry(plant, yaw, at, out);
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
            if (!grow(s->name, rng.next(), yaw, {x, 0, z}, false)) return false;
            ++stats.plants;
            for (int k = 0; k < f.grassPerCell; ++k) {
                float gx = x + float(rng.uniform() - 0.5) * cell, gz = z + float(rng.uniform() - 0.5) * cell;
                if (!grow(f.grass, rng.next(), float(rng.uniform() * 360), {gx, 0, gz}, true)) return false;
                ++stats.grasses;
            }
        }
    }
    if (!sharing.empty() && !growTogether(f, sharing, out, stats, error, limits, placed)) return false;
    out.planarCurve = false;
    return true;
}

}  // namespace sprout
