#include <cmath>
#include <string>

#include "core/parser_impl.hpp"

namespace sprout::detail {
namespace {

DirectiveHandler integer(int Settings::*field, int min, int max, const char* what) {
    return [=](Parser& p, const SourceLine& line, std::string_view value) {
        auto v = p.constant(line, value);
        if (!v) return;
        if (*v != std::floor(*v) || *v < min || *v > max) {
            p.sink().error(line, value, std::string(what) + " must be a whole number from " +
                                            std::to_string(min) + " to " + std::to_string(max));
            return;
        }
        p.grammar().settings.*field = int(*v);
    };
}

DirectiveHandler number(double Settings::*field, double min, double max, const char* what) {
    return [=](Parser& p, const SourceLine& line, std::string_view value) {
        auto v = p.constant(line, value);
        if (!v) return;
        if (!(*v >= min && *v <= max)) {
            p.sink().error(line, value, std::string(what) + " must be between " + std::to_string(min) +
                                            " and " + std::to_string(max));
            return;
        }
        p.grammar().settings.*field = *v;
    };
}

DirectiveHandler jittered(Jittered Settings::*field) {
    return [=](Parser& p, const SourceLine& line, std::string_view value) {
        if (auto j = p.jittered(line, value)) p.grammar().settings.*field = *j;
    };
}

void seed(Parser& p, const SourceLine& line, std::string_view value) {
    std::uint64_t v = 0;
    bool ok = !value.empty();
    for (char c : value) {
        if (c < '0' || c > '9' || v > (UINT64_MAX - std::uint64_t(c - '0')) / 10) {
            ok = false;
            break;
        }
        v = v * 10 + std::uint64_t(c - '0');
    }
    if (!ok) {
        p.sink().error(line, value, "the seed must be a whole number such as 'seed: 42'");
        return;
    }
    p.grammar().settings.seed = v;
}

}  // namespace

const std::vector<Directive>& directives() {
    static const std::vector<Directive> k = {
        {"module", [](Parser& p, const SourceLine& l, std::string_view v) { p.declareModules(l, v); }, 0},
        {"define", [](Parser& p, const SourceLine& l, std::string_view v) { p.define(l, v); }, 1},
        {"n", integer(&Settings::iterations, 0, kMaxIterations, "n")},
        {"iterations", integer(&Settings::iterations, 0, kMaxIterations, "iterations")},
        {"angle", jittered(&Settings::angle)},
        {"step", jittered(&Settings::step)},
        {"width", number(&Settings::width, 0, 1e6, "width")},
        {"seed", seed},
        {"axiom", [](Parser& p, const SourceLine& l, std::string_view v) { p.setAxiom(l, v); }},
        {"ignore", [](Parser& p, const SourceLine& l, std::string_view v) { p.setIgnore(l, v); }},
    };
    return k;
}

}  // namespace sprout::detail
