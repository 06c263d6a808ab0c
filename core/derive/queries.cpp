// Open L-systems and cpfg's query modules: between derivation steps the string is drawn by
// the turtle, and each ?P ?H ?U ?L receives the turtle's frame where it stands, each ?E the
// environment's answer there (core/environment/environment.hpp). One plant or a forest's
// plants together, in one shared environment.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/derive/derive.hpp"
#include "core/derive/draw.hpp"
#include "core/environment/environment.hpp"

namespace sprout {

bool answerQueries(const Grammar& grammar, ModuleString& s, int step, std::uint64_t seed, std::string* error, ProgramRun* run,
                   bool askProgram) {
    std::vector<QueryTarget> one{{&grammar, &s, step, seed}};
    return answerQueriesTogether(grammar.environment, seed, one, error, run, askProgram);
}

namespace {

// A plant's frame turned by `yaw` degrees about +Y (forests), and back.
glm::dvec3 turnBy(const glm::dvec3& v, double yaw) {
    const double c = std::cos(yaw * 3.14159265358979 / 180), s = std::sin(yaw * 3.14159265358979 / 180);
    return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}

// A float turtle's value to the digits it holds (7 significant), so that its last bits do not
// show as 2.9999998; below 5e-7 it is 0 (a unit vector's rounding noise). Rounding to a fixed
// 1e-5 instead lost digits that cpfg's double turtle keeps: a ?H's y of 0.53 read 1e-5 apart.
double turtleDigits(float v) {
    const double d = v;
    if (!std::isfinite(d)) return d;
    if (std::fabs(d) < 5e-7) return 0.0;
    const double scale = std::pow(10.0, 6 - int(std::floor(std::log10(std::fabs(d)))));
    return std::round(d * scale) / scale + 0.0;
}

// What a cpfg program answers arrives as text (%g) read back: 0.3, not the float nearest it.
double fromText(float v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return std::strtod(buf, nullptr) + 0.0;
}

// Each ?E of every plant whose pass is answerable, in the turtle's order: `fn(plant, its
// frame, its parameters, their count)`; the other query modules use up their frames.
template <class Pass, class Fn>
void forEachE(std::vector<QueryTarget>& targets, std::vector<Pass>& passes, Fn fn) {
    for (size_t t = 0; t < targets.size(); ++t) {
        if (!passes[t].answerable) continue;
        ModuleString& s = *targets[t].string;
        const Alphabet& alphabet = targets[t].grammar->alphabet;
        size_t q = 0, pp = 0;
        for (size_t i = 0; i < s.size(); ++i) {
            const SymbolId id = s.symbols[i];
            const unsigned a = alphabet[id].arity;
            if (passes[t].kind[id]) {
                const QueryFrame& f = passes[t].frames[q++];
                if (passes[t].kind[id] == 'E') fn(t, f, s.params.data() + pp, a);
            }
            pp += a;
        }
    }
}

// A cpfg environment program (`-e`): every ?E of every plant, in the turtle's order, is sent
// with the turtle where it stands, then the answers are set (libs/comm's semantics: only the
// parameters the program sets; no more than the ?E has).
template <class Pass, class ToWorld>
void answerByProgram(const EnvironmentProgram& program, ProgramRun& run, std::vector<QueryTarget>& targets,
                     std::vector<Pass>& passes, ToWorld toWorld) {
    std::vector<ProgramQuery> queries;
    std::vector<std::pair<double*, unsigned>> where;
    forEachE(targets, passes, [&](size_t t, const QueryFrame& f, double* params, unsigned a) {
        ProgramQuery query;
        for (unsigned k = 0; k < a; ++k) query.params.push_back(throughText(params[k]));
        const glm::dvec3 p = toWorld(targets[t], f.position);
        const glm::dvec3 h = turnBy(glm::dvec3(f.heading), targets[t].yaw), l = turnBy(glm::dvec3(f.left), targets[t].yaw),
                         u = turnBy(glm::dvec3(f.up), targets[t].yaw);
        const float pf[3] = {float(p.x), float(p.y), float(p.z)}, hf[3] = {float(h.x), float(h.y), float(h.z)},
                    lf[3] = {float(l.x), float(l.y), float(l.z)}, uf[3] = {float(u.x), float(u.y), float(u.z)};
        program.receive(pf, hf, lf, uf, query);
        queries.push_back(std::move(query));
        where.push_back({params, a});
    });
    if (program.sendsQueries) run.pass(queries);
    for (size_t k = 0; k < queries.size(); ++k) {
        const ProgramQuery& q = queries[k];
        for (size_t i = 0; i < q.answer.size() && i < where[k].second; ++i)
            if (i < q.set.size() && q.set[i]) where[k].first[i] = fromText(q.answer[i]);
    }
}

}  // namespace

bool answerQueriesTogether(const Environment& env, std::uint64_t envSeed, std::vector<QueryTarget>& targets, std::string* error,
                           ProgramRun* run, bool askProgram) {
    if (targets.empty()) return true;
    struct Pass {
        std::vector<QueryFrame> frames;
        Geometry grown;
        std::vector<char> kind;
        bool answerable = false;
    };
    std::vector<Pass> passes(targets.size());
    for (size_t t = 0; t < targets.size(); ++t) {
        const QueryTarget& q = targets[t];
        Pass& pass = passes[t];
        TurtleOptions o{q.step, q.seed, nullptr};
        o.fromTree = false;
        o.queries = &pass.frames;
        interpret(*q.string, *q.grammar, o, pass.grown);
        // Frames come in drawing order; a homomorphism that drops or repeats query modules
        // would break the correspondence, and then the parameters are left as they were.
        const Alphabet& alphabet = q.grammar->alphabet;
        pass.kind.assign(alphabet.size(), 0);
        for (size_t k = 0; k < alphabet.size(); ++k) pass.kind[k] = queryKind(alphabet[SymbolId(k)].name);
        size_t count = 0;
        for (SymbolId id : q.string->symbols) count += pass.kind[id] != 0;
        pass.answerable = count == pass.frames.size();
    }
    // What the environment sees: every plant where it stands. One plant at the origin is its
    // own geometry.
    const bool placed = targets.size() > 1 || targets[0].yaw != 0 || targets[0].at != glm::dvec3(0.0);
    Geometry world;
    const Geometry* grown = &passes[0].grown;
    if (placed && (env.isLight() || env.isAttraction())) {
        for (size_t t = 0; t < targets.size(); ++t)
            placeGeometry(passes[t].grown, float(targets[t].yaw), glm::vec3(targets[t].at), world);
        grown = &world;
    }
    LightGrid light;
    if (env.isLight()) {
        std::string why;
        if (!buildLight(env, *grown, light, why)) {
            if (error) *error = why;
            return false;
        }
    }
    auto toWorld = [&](const QueryTarget& q, const glm::vec3& p) { return turnBy(glm::dvec3(p), q.yaw) + q.at; };
    // Directions in an answer go back into the plant's own frame.
    auto directionBack = [&](const QueryTarget& q, double* out, int count) {
        if (q.yaw == 0 || count < 3) return;
        const glm::dvec3 v = turnBy(glm::dvec3(out[0], out[1], out[2]), -q.yaw);
        for (int k = 0; k < 3; ++k) out[k] = std::round(v[k] * 1e5) / 1e5 + 0.0;
    };
    if (env.isProgram() && askProgram) {
        std::unique_ptr<ProgramRun> own;
        if (!run) own = env.program->start(), run = own.get();
        answerByProgram(*env.program, *run, targets, passes, toWorld);
    }
    if (env.isAttraction()) {
        // Space colonisation answers every bud at once, of every plant: a point pulls only its
        // nearest bud.
        std::vector<glm::dvec3> buds;
        std::vector<double*> params;
        std::vector<int> arities;
        std::vector<size_t> owner;
        forEachE(targets, passes, [&](size_t t, const QueryFrame& f, double* p, unsigned a) {
            buds.push_back(toWorld(targets[t], f.position));
            params.push_back(p);  // a ?E without parameters: none there
            arities.push_back(int(a));
            owner.push_back(t);
        });
        answerAttraction(env, buds, freePoints(env, *grown, envSeed), params, arities);
        for (size_t b = 0; b < buds.size(); ++b) directionBack(targets[owner[b]], params[b], std::min(arities[b], 3));
    }
    for (size_t t = 0; t < targets.size(); ++t) {
        if (!passes[t].answerable) continue;
        const QueryTarget& target = targets[t];
        ModuleString& s = *target.string;
        const Alphabet& alphabet = target.grammar->alphabet;
        const std::vector<char>& kind = passes[t].kind;
        size_t q = 0, pp = 0;
        for (size_t i = 0; i < s.size(); ++i) {
            const SymbolId id = s.symbols[i];
            const unsigned a = alphabet[id].arity;
            if (kind[id] == 'E') {  // a communication module: the environment answers (open L-systems)
                const QueryFrame& f = passes[t].frames[q++];
                if (env.isAttraction() || env.isProgram()) {  // answered above: the ?E only uses up its frame here
                } else if (env.empty()) {  // no environment (an L-system Explorer file's ?E): it keeps its values
                } else {
                    const glm::dvec3 p = toWorld(target, f.position), h = turnBy(glm::dvec3(f.heading), target.yaw);
                    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && glm::length(h) > 0)) {
                        // No answer can be right there, and a NaN would spread through the rules.
                        if (error)
                            *error = std::string(targets.size() > 1 ? "plant " + std::to_string(t + 1) + ": " : "") + "the ?E at module " +
                                     std::to_string(i + 1) + " of the string is at a point that is not a number (the turtle's "
                                     "moves before it are NaN or infinite, e.g. F of a parameter that overflowed): the "
                                     "environment cannot answer it";
                        return false;
                    }
                    // A ?E without parameters (the string may hold none at all) is asked, and told
                    // nothing: no reference into an empty buffer is made for it.
                    answer(env, p, glm::normalize(h), s.params.data() + pp, int(a), &light);
                    if ((!env.obstacles.empty() || env.ground) && a >= 5) directionBack(target, s.params.data() + pp + 2, int(a) - 2);
                }
            } else if (kind[id]) {
                const QueryFrame& f = passes[t].frames[q++];
                const glm::vec3& v = kind[id] == 'P' ? f.position : kind[id] == 'H' ? f.heading : kind[id] == 'U' ? f.up : f.left;
                for (unsigned k = 0; k < a && k < 3; ++k) s.params[pp + k] = turtleDigits(v[int(k)]);
            }
            pp += a;
        }
    }
    return true;
}

}  // namespace sprout
