#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/base/bounded.hpp"
#include "core/language/parser_impl.hpp"

namespace sprout::detail {
namespace {

DirectiveHandler integer(int Settings::*field, int min, int max, const char* what) {
    return [=](Parser& p, const SourceLine& line, std::string_view value) {
        auto v = p.constant(line, value);
        if (!v) return;
        const auto whole = wholeIn(*v, min, max);
        if (!whole) {
            p.sink().error(line, value, std::string(what) + " must be a whole number from " +
                                            std::to_string(min) + " to " + std::to_string(max));
            return;
        }
        p.grammar().settings.*field = int(*whole);
    };
}

DirectiveHandler number(double Settings::*field, double min, double max, const char* what) {
    return [=](Parser& p, const SourceLine& line, std::string_view value) {
        auto v = p.constant(line, value);
        if (!v) return;
        if (!inRange(*v, min, max)) {
            p.sink().error(line, value, std::string(what) + " must be between " + formatNumber(min) + " and " + formatNumber(max));
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
    if (!ok && p.cpfg()) {  // cpfg: an expression (`seed: SEED`)
        if (auto c = p.constant(line, value); c && *c >= 0 && *c < 1e18) ok = true, v = std::uint64_t(*c);
    }
    if (!ok) {
        p.sink().error(line, value, "the seed must be a whole number such as 'seed: 42'");
        return;
    }
    p.grammar().settings.seed = v;
    p.grammar().settings.seedGiven = true;
}

std::optional<std::uint32_t> colour(std::string_view word) {
    if (word.starts_with("#")) word.remove_prefix(1);
    if (word.size() != 6 && word.size() != 8) return std::nullopt;
    std::uint32_t v = 0;
    for (char c : word) {
        int d = std::isdigit(static_cast<unsigned char>(c)) ? c - '0'
                : (c >= 'a' && c <= 'f') ? c - 'a' + 10 : (c >= 'A' && c <= 'F') ? c - 'A' + 10 : -1;
        if (d < 0) return std::nullopt;
        v = v << 4 | std::uint32_t(d);
    }
    return word.size() == 6 ? (v << 8 | 0xFF) : v;
}

std::vector<std::string_view> words(std::string_view text) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && (isSpace(text[i]) || text[i] == ',')) ++i;
        size_t start = i;
        while (i < text.size() && !isSpace(text[i]) && text[i] != ',') ++i;
        if (i > start) out.push_back(text.substr(start, i - start));
    }
    return out;
}

bool colours(Parser& p, const SourceLine& line, std::string_view text, std::vector<std::uint32_t>& out) {
    for (auto w : words(text)) {
        auto c = colour(w);
        if (!c) {
            p.sink().error(line, w, "'" + std::string(w) + "' is not a colour: write it as #rrggbb, e.g. #6b4a2e");
            return false;
        }
        out.push_back(*c);
    }
    return true;
}

void branchScale(Parser& p, const SourceLine& line, std::string_view value) {
    auto v = p.numbers(line, value, 1, 2, "branch_scale: 0.8 0.7");
    if (!v) return;
    for (double x : *v)
        if (!(x > 0 && x <= 10)) return p.sink().error(line, value, "branch_scale factors must be greater than 0 and at most 10");
    p.grammar().settings.branchLength = (*v)[0];
    p.grammar().settings.branchWidth = v->size() > 1 ? (*v)[1] : (*v)[0];
}

void tropism(Parser& p, const SourceLine& line, std::string_view value) {
    auto v = p.numbers(line, value, 4, 4, "tropism: 0 -1 0 0.2");
    if (!v) return;
    auto& s = p.grammar().settings;
    s.tropism = {(*v)[0], (*v)[1], (*v)[2]};
    s.tropismStrength = (*v)[3];
    if ((*v)[0] == 0 && (*v)[1] == 0 && (*v)[2] == 0)
        p.sink().error(line, value, "the tropism direction cannot be 0 0 0");
}

void palette(Parser& p, const SourceLine& line, std::string_view value) {
    std::vector<std::uint32_t> c;
    if (colours(p, line, value, c)) {
        if (c.empty()) return p.sink().error(line, value, "list colours, as in 'palette: #6b4a2e #7db344'");
        p.grammar().settings.palette = std::move(c);
    }
}

// material: INDEX #rrggbb [transparency T] [specular #rrggbb] [shininess S] [emission #rrggbb]
// [texture FILE]: a palette entry, how much light it lets through, how it shines, its image.
void material(Parser& p, const SourceLine& line, std::string_view value) {
    const std::vector<std::string_view> w = words(value);
    const char* example = "as in 'material: 3 #3070ff transparency 0.5'";
    int index = -1;
    if (w.empty() || std::sscanf(std::string(w[0]).c_str(), "%d", &index) != 1 || index < 0 || index > 255 ||
        w[0].find_first_not_of("0123456789") != std::string_view::npos)
        return p.sink().error(line, w.empty() ? value : w[0], std::string("a material begins with its index, 0 to 255, ") + example);
    const auto c = w.size() > 1 ? colour(w[1]) : std::nullopt;
    if (!c) return p.sink().error(line, w.size() > 1 ? w[1] : value, std::string("then its colour as #rrggbb, ") + example);
    std::uint32_t rgba = *c;
    Shine shine;
    std::string texture;
    for (size_t k = 2; k < w.size(); k += 2) {
        const std::string_view field = w[k], v = k + 1 < w.size() ? w[k + 1] : w[k];
        if (field == "texture") {  // an image file, beside the model or a path
            if (k + 1 >= w.size()) return p.sink().error(line, field, "texture is followed by an image file, as in 'texture bark.png'");
            texture = std::string(v);
            const std::string& folder = p.options().folder;
            if (!folder.empty() && texture.front() != '/') texture = folder + "/" + texture;
            std::error_code ec;
            if (!folder.empty() && !std::filesystem::is_regular_file(texture, ec))
                p.sink().warning(line, v, "no image file '" + std::string(v) + "' beside the model: drawn in its colour");
            continue;
        }
        if (field == "specular" || field == "emission") {
            const auto rgb = k + 1 < w.size() ? colour(v) : std::nullopt;
            if (!rgb) return p.sink().error(line, v, std::string(field) + " is a colour, #rrggbb");
            (field == "specular" ? shine.specular : shine.emission) = *rgb & 0xFFFFFF00u;
            continue;
        }
        if (field != "transparency" && field != "shininess")
            return p.sink().error(line, field, "'" + std::string(field) +
                                                   "' is not a material's field: transparency, specular, shininess, emission, texture");
        const auto t = k + 1 < w.size() ? p.constant(line, v) : std::nullopt;
        if (!t || !inRange(*t, 0, 1)) return p.sink().error(line, v, std::string(field) + " is from 0 to 1");
        if (field == "shininess") shine.shininess = float(*t);
        else rgba = (rgba & 0xFFFFFF00u) | std::uint32_t(std::lround((1 - *t) * 255));
    }
    p.grammar().settings.materials.push_back({index, rgba});
    if (!shine.plain()) p.grammar().settings.shines.push_back({index, shine});
    if (!texture.empty()) p.grammar().settings.textures.push_back({index, std::move(texture)});
}

void gradient(Parser& p, const SourceLine& line, std::string_view value) {
    auto& s = p.grammar().settings;
    if (value == "off" || value == "no") return void(s.gradient = Toggle::Off);
    if (value == "on" || value == "yes") return void(s.gradient = Toggle::On);
    std::vector<std::uint32_t> c;
    if (!colours(p, line, value, c)) return;
    if (c.size() != 2) return p.sink().error(line, value, "expected 'gradient: on', 'off' or two colours, bark then tip");
    s.gradient = Toggle::On;
    s.barkColour = c[0];
    s.tipColour = c[1];
}

void view(Parser& p, const SourceLine& line, std::string_view value) {
    auto& s = p.grammar().settings;
    if (value == "2d") s.view = ViewHint::Flat;
    else if (value == "3d") s.view = ViewHint::Solid;
    else if (value == "auto") s.view = ViewHint::Auto;
    else p.sink().error(line, value, "expected 'view: 2d', '3d' or 'auto'");
}

void environment(Parser& p, const SourceLine& line, std::string_view text) {
    // Keywords first (obstacle, ground, the shape), then numbers: expressions of defines.
    std::vector<std::string> words;
    std::vector<double> numbers;
    for (const auto& [start, end] : environmentTokens(text)) {
        std::string_view token = text.substr(start, end - start);
        const bool keyword = isEnvironmentKeyword(token);
        if (keyword) {
            words.emplace_back(token);
        } else if (std::isalpha(static_cast<unsigned char>(token[0])) && numbers.empty() && !p.grammar().defines.count(std::string(token))) {
            words.emplace_back(token);  // an unknown kind: declare() names it
        } else {
            auto v = p.constant(line, token);
            if (!v) return;
            if (!inRange(*v, -Environment::kMaxNumber, Environment::kMaxNumber))
                return p.sink().error(line, token, "'" + std::string(token) + "' is " + formatNumber(*v) +
                                                        ": an environment's numbers go from -1e9 to 1e9");
            numbers.push_back(*v);
        }
    }
    std::string error;
    if (words.size() == 2 && words[0] == "mesh" && numbers.empty()) {
        // A closed mesh beside the grammar, read with the same folder rules as #include.
        const std::string& file = words[1];
        auto fail = [&](const std::string& why) { p.sink().error(line, trim(text), why); };
        if (!p.options().include) return fail("the mesh '" + file + "' needs the grammar's folder: save the grammar beside it first");
        auto bytes = p.options().include(file, error);
        if (!bytes) return fail("cannot read the mesh '" + file + "': " + error);
        auto mesh = std::make_shared<TriMesh>();
        if (!mesh->parse(*bytes, error)) return fail("'" + file + "' cannot be the environment: " + error);
        if (!p.grammar().environment.declareMesh(std::move(mesh), error)) fail(error);
        return;
    }
    if (!p.grammar().environment.declare(words, numbers, error)) p.sink().error(line, trim(text).empty() ? line.text : trim(text), error);
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
        {"width_factor", number(&Settings::widthFactor, 0.001, 1000, "width_factor")},
        {"branch_scale", branchScale},
        {"step_scale", number(&Settings::stepScale, 1e-6, 1e6, "step_scale")},
        {"tropism", tropism},
        {"palette", palette},
        {"material", material},
        {"gradient", gradient},
        {"view", view},
        {"seed", seed, 0},  // before anything that may call rand()
        {"axiom", [](Parser& p, const SourceLine& l, std::string_view v) { p.setAxiom(l, v); }},
        {"ignore", [](Parser& p, const SourceLine& l, std::string_view v) { p.setIgnore(l, v); }},
        {"environment", environment, 1},
        // before the rules, whose expressions name them (func, @#)
        {"function", [](Parser& p, const SourceLine& l, std::string_view v) { p.addFunction(l, v); }, 1},
        {"contour", [](Parser& p, const SourceLine& l, std::string_view v) { p.addContour(l, v); }, 1},
    };
    return k;
}

const Directive* directiveNamed(std::string_view name) {
    for (const auto& d : directives())
        if (name == d.name) return &d;
    return nullptr;
}

}  // namespace sprout::detail
