// sprout expand FILE|PRESET [-n N] [--seed S] [--stats] [--max-modules M] [--max-memory MB]
// Prints the derived string of step N: module names concatenated, parameters as
// name(p1,p2) in shortest round-trip form. The test oracle relies on this format.
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <vector>

#include "app/args.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/load.hpp"
#include "app/plant/growth.hpp"
#include "core/derive/derive.hpp"
#include "core/base/atomic_file.hpp"

namespace sprout::cli {
namespace {

// Standard output in large writes from one reusable buffer (no stdio per module), through the
// writer every file goes through ("-" is standard output there).
class Output {
public:
    // Not zeroed: its pages are touched only as far as the string goes (zeroing 4 MB was most
    // of a small object's `sprout expand`).
    Output() : m_buffer(new char[kSize]) {
        std::string error;
        m_file.open("-", error);
    }
    char* reserve(std::size_t n) {
        if (m_used + n > kSize) flush();
        return m_buffer.get() + m_used;
    }
    void commit(std::size_t n) { m_used += n; }
    // False after a closed pipe or a full disk: the exit status says so.
    bool flush() {
        m_file.write(m_buffer.get(), m_used);
        m_used = 0;
        return m_file.ok();
    }
    static constexpr std::size_t kSize = 4 << 20;

private:
    AtomicFile m_file;
    std::unique_ptr<char[]> m_buffer;
    std::size_t m_used = 0;
};

// The string as `toString` prints it, at the speed of a table lookup: a string of one-letter
// modules is one byte per symbol, translated a block at a time; parameters are written with
// std::to_chars (shortest round-trip form).
bool writeString(const ModuleString& s, const Alphabet& alphabet) {
    Output out;
    const std::size_t N = s.size(), A = alphabet.size();
    const SymbolId* sym = s.symbols.data();
    bool oneByte = s.params.empty();
    std::vector<unsigned char> table(A);
    for (std::size_t k = 0; k < A && oneByte; ++k) {
        const std::string& name = alphabet[SymbolId(k)].name;
        oneByte = name.size() == 1;
        if (oneByte) table[k] = static_cast<unsigned char>(name[0]);
    }
    if (oneByte) {
        const unsigned char* t = table.data();
        for (std::size_t i = 0; i < N;) {
            const std::size_t n = std::min(N - i, Output::kSize);
            char* dst = out.reserve(n);
            for (std::size_t k = 0; k < n; ++k) dst[k] = char(t[sym[i + k]]);
            out.commit(n);
            i += n;
        }
    } else {
        const double* p = s.params.data();
        const bool floats = alphabet.floatParameters;
        for (std::size_t i = 0; i < N; ++i) {
            const SymbolInfo& info = alphabet[sym[i]];
            if (info.nameArgs) {  // a parameter written as a quoted name prints as that name
                std::string m;
                appendModule(m, info, p, &alphabet);
                std::memcpy(out.reserve(m.size()), m.data(), m.size());
                out.commit(m.size());
                p += info.arity;
                continue;
            }
            // Name, '(', up to 32 numbers of at most 24 characters, ',' and ')'.
            char* dst = out.reserve(info.name.size() + 2 + std::size_t(info.arity) * 26);
            char* at = dst;
            std::memcpy(at, info.name.data(), info.name.size());
            at += info.name.size();
            if (info.arity) {
                *at++ = '(';
                for (int k = 0; k < info.arity; ++k) {
                    if (k) *at++ = ',';
                    if (floats && double(float(p[k])) == p[k]) at = std::to_chars(at, at + 25, float(p[k])).ptr;  // cpfg's
                    else at = std::to_chars(at, at + 25, p[k]).ptr;
                }
                *at++ = ')';
                p += info.arity;
            }
            out.commit(std::size_t(at - dst));
        }
    }
    *out.reserve(1) = '\n';
    out.commit(1);
    return out.flush();
}

// How the text was read: its dialect and each setting taken from it, with its line (a user
// who pasted text sees how Sprout understood it).
void printReadAs(const LoadedGrammar& loaded) {
    std::printf("read as: %s\n", loaded.dialect.c_str());
    for (const auto& line : settingsReadLines(*loaded.grammar)) std::printf("  %s\n", line.c_str());
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
    Args args(argc, argv, 1, {"--stats", "--no-python"}, {"-n", "--seed", "--max-modules", "--max-memory"});
    auto n = args.integer("-n", 0, 10000);
    auto seed = args.integer("--seed", 0, INT64_MAX);
    auto maxModules = args.integer("--max-modules", 1, INT64_MAX);
    auto maxMemory = args.integer("--max-memory", 1, INT64_MAX / (1 << 20));
    if (!args.error().empty() || args.positionals().size() != 1) {
        std::cerr << "sprout expand: " << (args.error().empty() ? "expects one FILE or PRESET" : args.error())
                  << "\nusage: sprout expand FILE|PRESET [-n N] [--seed S] [--stats] "
                     "[--max-modules M] [--max-memory MB] [--no-python]\n"
                     "       An L-Py model (.lpy) is a Python program: it runs as `python3 FILE` would; --no-python refuses it.\n";
        return 2;
    }
    LoadOptions lo;
    lo.steps = n ? int(*n) : -1;
    lo.python = !args.flag("--no-python");
    if (maxModules) lo.maxModules = std::uint64_t(*maxModules);
    if (maxMemory) lo.maxBytes = std::uint64_t(*maxMemory) << 20;
    auto loaded = loadGrammar(args.positionals()[0], lo);
    if (!loaded) return 1;
    if (args.flag("--stats")) printReadAs(*loaded);
    if (loaded->ranPython && !args.flag("--stats")) {
        std::fwrite(loaded->derived.data(), 1, loaded->derived.size(), stdout);
        std::fputc('\n', stdout);
        return std::fflush(stdout) == 0 ? 0 : 1;
    }

    DeriveOptions options;
    if (seed) options.seed = std::uint64_t(*seed);
    if (maxModules) options.limits.maxModules = std::uint64_t(*maxModules);
    if (maxMemory) options.limits.maxBytes = std::uint64_t(*maxMemory) << 20;
    Growth growth(loaded->grammar, options);
    int steps = n ? int(*n) : loaded->grammar->settings.iterations;
    DeriveOutcome outcome = growth.derive(steps);
    if (!outcome.ok()) {
        std::cerr << loaded->displayName << ": " << outcome.message << "\n";
        return 1;
    }
    if (args.flag("--stats")) printStats(growth.derivation(), steps, loaded->displayName);
    else if (!writeString(*growth.step(steps), loaded->grammar->alphabet)) return 1;
    return std::fflush(stdout) == 0 ? 0 : 1;
}

}  // namespace sprout::cli
