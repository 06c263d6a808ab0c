// sprout expand FILE|PRESET [-n N] [--seed S] [--stats] [--max-modules M] [--max-memory MB]
// Prints the derived string of step N: module names concatenated, parameters as
// name(p1,p2) in shortest round-trip form. The test oracle relies on this format.
#include <cstdio>
#include <iostream>

#include "app/cli/args.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/load.hpp"
#include "core/derive.hpp"

namespace sprout::cli {
namespace {

void writeString(const ModuleString& s, const Alphabet& alphabet) {
    std::string chunk;
    chunk.reserve(1 << 20);
    const double* p = s.params.data();
    for (SymbolId id : s.symbols) {
        const SymbolInfo& info = alphabet[id];
        appendModule(chunk, info, p);
        p += info.arity;
        if (chunk.size() >= (1 << 20) - 256) {
            std::fwrite(chunk.data(), 1, chunk.size(), stdout);
            chunk.clear();
        }
    }
    chunk += '\n';
    std::fwrite(chunk.data(), 1, chunk.size(), stdout);
}

void printStats(Derivation& d, int n, const std::string& name) {
    const Grammar& g = d.grammar();
    std::printf("%s: %s%s%s, seed %llu\n", name.c_str(), g.parametric() ? "parametric" : "non-parametric",
                g.hasContext() ? ", context-sensitive" : "", g.stochastic() ? ", stochastic" : "",
                static_cast<unsigned long long>(d.seed()));
    std::printf("engine: %s\n", d.fastPath() ? "D0L block expansion (each step written from the axiom)"
                                             : "step rewriting (each step from the previous one, all kept)");
    std::printf("%5s %15s %15s %-15s %12s\n", "step", "modules", "parameters", "kind", "time (ms)");
    for (int k = 0; k <= n; ++k) {
        auto s = d.step(k);
        const StepStats& st = d.stats()[size_t(k)];
        std::printf("%5d %15s %15s %-15s %12.3f\n", k, withThousands(s->size()).c_str(),
                    withThousands(s->params.size()).c_str(),
                    s->params.empty() ? "non-parametric" : "parametric", st.millis);
    }
}

}  // namespace

int runExpand(int argc, char** argv) {
    Args args(argc, argv, 1, {"--stats"}, {"-n", "--seed", "--max-modules", "--max-memory"});
    auto n = args.integer("-n", 0, 10000);
    auto seed = args.integer("--seed", 0, INT64_MAX);
    auto maxModules = args.integer("--max-modules", 1, INT64_MAX);
    auto maxMemory = args.integer("--max-memory", 1, INT64_MAX / (1 << 20));
    if (!args.error().empty() || args.positionals().size() != 1) {
        std::cerr << "sprout expand: " << (args.error().empty() ? "expects one FILE or PRESET" : args.error())
                  << "\nusage: sprout expand FILE|PRESET [-n N] [--seed S] [--stats] "
                     "[--max-modules M] [--max-memory MB]\n";
        return 2;
    }
    auto loaded = loadGrammar(args.positionals()[0]);
    if (!loaded) return 1;

    DeriveOptions options;
    if (seed) options.seed = std::uint64_t(*seed);
    if (maxModules) options.limits.maxModules = std::uint64_t(*maxModules);
    if (maxMemory) options.limits.maxBytes = std::uint64_t(*maxMemory) << 20;
    Derivation derivation(loaded->grammar, options);
    int steps = n ? int(*n) : loaded->grammar->settings.iterations;
    DeriveOutcome outcome = derivation.deriveTo(steps);
    if (!outcome.ok()) {
        std::cerr << loaded->displayName << ": " << outcome.message << "\n";
        return 1;
    }
    if (args.flag("--stats")) printStats(derivation, steps, loaded->displayName);
    else writeString(*derivation.step(steps), loaded->grammar->alphabet);
    return std::fflush(stdout) == 0 ? 0 : 1;
}

}  // namespace sprout::cli
