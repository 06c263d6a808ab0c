// An L-Py model's materials, read and written in its text (lpy_materials.hpp).
#include "app/plant/lpy_materials.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/plant/python_text.hpp"

namespace sprout {
namespace {

using namespace python_text;

const char* kFields[] = {"ambient", "diffuse", "specular", "emission", "shininess", "transparency"};

struct Arg {
    std::string key;           // "" for a positional one
    size_t begin = 0, end = 0;  // the value's bytes, spaces trimmed
};

// The arguments of the call whose '(' is at `open` and ')' at `close`.
std::vector<Arg> arguments(std::string_view t, size_t open, size_t close) {
    std::vector<Arg> out;
    size_t start = open + 1;
    int depth = 0;
    for (size_t k = open + 1; k <= close; ++k) {
        const char c = t[k];
        if (c == '\'' || c == '"') {
            const size_t q = t.find(c, k + 1);
            if (q == std::string_view::npos || q > close) break;
            k = q;
        } else if (c == '(' || c == '[') {
            ++depth;
        } else if ((c == ')' || c == ']') && depth > 0) {
            --depth;
        } else if ((c == ',' && depth == 0) || k == close) {
            size_t b = skipSpace(t, start), e = k;
            while (e > b && std::isspace(static_cast<unsigned char>(t[e - 1]))) --e;
            if (e > b) {
                Arg a;
                size_t id = b;
                while (id < e && isIdent(t[id])) ++id;
                size_t eq = skipSpace(t, id);
                if (id > b && eq < e && t[eq] == '=' && (eq + 1 >= e || t[eq + 1] != '=')) {
                    a.key = std::string(t.substr(b, id - b));
                    b = skipSpace(t, eq + 1);
                }
                a.begin = b, a.end = e;
                out.push_back(a);
            }
            start = k + 1;
        }
    }
    return out;
}

// `Color3(r,g,b)` or `(r,g,b)`.
std::optional<std::array<int, 3>> colour(std::string_view v) {
    const size_t open = v.find('('), close = v.rfind(')');
    if (open == std::string_view::npos || close == std::string_view::npos || close < open) return std::nullopt;
    std::array<int, 3> c{};
    size_t b = open + 1;
    for (int i = 0; i < 3; ++i) {
        size_t comma = i < 2 ? v.find(',', b) : close;
        if (comma == std::string_view::npos || comma > close) return std::nullopt;
        const auto n = number(v.substr(b, comma - b));
        if (!n) return std::nullopt;
        c[size_t(i)] = int(std::lround(std::clamp(*n, -1e6, 1e6)));
        b = comma + 1;
    }
    return c;
}

std::string unquoted(std::string_view v) {
    if (v.size() >= 2 && (v.front() == '\'' || v.front() == '"') && v.back() == v.front()) return std::string(v.substr(1, v.size() - 2));
    return std::string(v);
}

// The material call whose '(' is at `open`: its fields and where they are.
std::optional<LpyMaterial> materialCall(std::string_view t, size_t open) {
    const size_t close = closing(t, open);
    if (close == std::string_view::npos) return std::nullopt;
    LpyMaterial m;
    m.insertAt = close;
    size_t position = 0;
    for (const Arg& a : arguments(t, open, close)) {
        const std::string_view v = t.substr(a.begin, a.end - a.begin);
        int field = -1;  // 0 name, then 1 + Field
        if (a.key.empty()) {
            field = int(position++);
            if (field > 0) m.keywords = false;
        } else if (a.key == "name") {
            field = 0;
        } else {
            for (int f = 0; f < 6; ++f)
                if (a.key == kFields[f]) field = f + 1;
        }
        if (field == 0) {
            m.name = unquoted(v);
            continue;
        }
        if (field < 1 || field > 6) continue;
        const auto f = LpyMaterial::Field(field - 1);
        if (f == LpyMaterial::Ambient || f == LpyMaterial::Specular || f == LpyMaterial::Emission) {
            const auto c = colour(v);
            if (!c) return std::nullopt;
            (f == LpyMaterial::Ambient ? m.ambient : f == LpyMaterial::Specular ? m.specular : m.emission) = *c;
        } else {
            const auto n = number(v);
            if (!n) return std::nullopt;
            (f == LpyMaterial::Diffuse ? m.diffuse : f == LpyMaterial::Shininess ? m.shininess : m.transparency) = *n;
        }
        m.spans[size_t(f)] = {a.begin, a.end};
    }
    return m;
}

// Where `NAME = [pgl.]CALL(` is last assigned before `before`: its '('.
size_t assignment(std::string_view t, std::string_view name, size_t before, std::string_view call) {
    size_t found = std::string_view::npos;
    for (size_t at = t.find(name); at != std::string_view::npos && at < before; at = t.find(name, at + 1)) {
        if (at > 0 && isIdent(t[at - 1])) continue;
        size_t k = at + name.size();
        if (!eat(t, k, "=")) continue;
        eat(t, k, "pgl.");
        if (!eat(t, k, call)) continue;
        k = skipSpace(t, k);
        if (k < t.size() && t[k] == '(') found = k;
    }
    return found;
}

// `ImageTexture('file')` or Studio's `ImageTexture("name" , "file" , )`: its image.
LpyMaterial texture(std::string_view t, size_t open) {
    LpyMaterial m;
    const size_t close = closing(t, open);
    const auto args = arguments(t, open, close == std::string_view::npos ? open : close);
    const Arg* file = args.size() >= 2 && args[1].key.empty() ? &args[1] : args.empty() ? nullptr : &args[0];
    for (const Arg& a : args)
        if (a.key == "filename") file = &a;
    m.texture = file ? unquoted(t.substr(file->begin, file->end - file->begin)) : "?";
    if (file && file->end > file->begin && (t[file->begin] == '\'' || t[file->begin] == '"')) m.textureSpan = {file->begin, file->end};
    return m;
}

// Studio's `Texture2D(image = NAME , )`, NAME an ImageTexture assigned before.
LpyMaterial texture2D(std::string_view t, size_t open) {
    const size_t close = closing(t, open);
    for (const Arg& a : arguments(t, open, close == std::string_view::npos ? open : close))
        if (a.key == "image" || a.key.empty()) {
            const size_t image = assignment(t, t.substr(a.begin, a.end - a.begin), open, "ImageTexture");
            if (image != std::string_view::npos) return texture(t, image);
        }
    LpyMaterial m;
    m.texture = "?";
    return m;
}

}  // namespace

std::vector<LpyMaterial> lpyMaterials(std::string_view text) {
    std::vector<LpyMaterial> out;
    for (size_t at = text.find("setMaterial"); at != std::string_view::npos; at = text.find("setMaterial", at + 11)) {
        size_t k = at + 11;
        if (!eat(text, k, "(")) continue;
        const size_t comma = text.find(',', k);
        if (comma == std::string_view::npos) continue;
        const auto index = number(text.substr(k, comma - k));
        if (!index || *index < 0 || *index != std::floor(*index)) continue;
        k = skipSpace(text, comma + 1);
        std::optional<LpyMaterial> m;
        size_t p = k;
        if (eat(text, p, "pgl."), eat(text, p, "ImageTexture") && eat(text, p, "(")) {
            m = texture(text, p - 1);
        } else if (p = k, eat(text, p, "pgl."), eat(text, p, "Material") && eat(text, p, "(")) {
            m = materialCall(text, p - 1);
        } else {
            size_t e = k;
            while (e < text.size() && isIdent(text[e])) ++e;
            const std::string_view name = text.substr(k, e - k);
            if (size_t open = e > k ? assignment(text, name, at, "Material") : std::string_view::npos; open != std::string_view::npos)
                m = materialCall(text, open);
            else if (open = e > k ? assignment(text, name, at, "Texture2D") : std::string_view::npos; open != std::string_view::npos)
                m = texture2D(text, open);
        }
        if (!m) continue;
        m->index = int(*index);
        m->line = int(std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n')) + 1;
        out.push_back(std::move(*m));
    }
    return out;
}

std::string setLpyMaterial(std::string_view text, const LpyMaterial& m, LpyMaterial::Field field, const LpyMaterial& value) {
    std::string v;
    auto colourText = [&](const std::array<int, 3>& c, bool color3) {
        const std::string inner = std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]);
        return color3 ? "Color3(" + inner + ")" : "(" + inner + ")";
    };
    const auto [b, e] = m.spans[size_t(field)];
    const bool color3 = b < e && text.substr(b, 6) == "Color3";
    switch (field) {
        case LpyMaterial::Ambient: v = colourText(value.ambient, color3); break;
        case LpyMaterial::Specular: v = colourText(value.specular, color3); break;
        case LpyMaterial::Emission: v = colourText(value.emission, color3); break;
        case LpyMaterial::Diffuse: v = formatted(value.diffuse); break;
        case LpyMaterial::Shininess: v = formatted(value.shininess); break;
        case LpyMaterial::Transparency: v = formatted(value.transparency); break;
    }
    std::string out(text);
    if (b < e) return out.replace(b, e - b, v);
    if (!m.keywords || !m.texture.empty() || m.insertAt == 0) return out;  // a positional call has every field
    // Studio's form: ` field = value , ` before the ')' (after the last ", " it left there).
    size_t before = m.insertAt;
    while (before > 0 && std::isspace(static_cast<unsigned char>(text[before - 1]))) --before;
    const bool separated = before > 0 && (text[before - 1] == ',' || text[before - 1] == '(');
    return out.insert(m.insertAt, std::string(separated ? "" : ", ") + kFields[field] + " = " + v + (separated ? " , " : ""));
}

std::string interpolateLpyMaterials(std::string_view text, int from, int to, std::string& error) {
    if (from > to) std::swap(from, to);
    auto at = [&](const std::vector<LpyMaterial>& all, int index) -> const LpyMaterial* {
        const LpyMaterial* found = nullptr;
        for (const LpyMaterial& m : all)
            if (m.index == index) found = &m;  // the last, which the turtle keeps
        return found && found->texture.empty() ? found : nullptr;
    };
    const std::vector<LpyMaterial> all = lpyMaterials(text);
    const LpyMaterial *a = at(all, from), *b = at(all, to);
    if (!a || !b) return error = "interpolating needs both ends set as materials (not textures)", "";
    if (to - from < 2) return error = "no material lies between " + std::to_string(from) + " and " + std::to_string(to), "";
    const LpyMaterial ea = *a, eb = *b;  // copies: the text changes below
    auto mix = [](int x, int y, double t) { return int(std::lround(x + (y - x) * t)); };
    std::string out(text);
    for (int k = from + 1; k < to; ++k) {
        const double t = double(k - from) / double(to - from);
        LpyMaterial v;
        for (size_t c = 0; c < 3; ++c) {
            v.ambient[c] = mix(ea.ambient[c], eb.ambient[c], t);
            v.specular[c] = mix(ea.specular[c], eb.specular[c], t);
            v.emission[c] = mix(ea.emission[c], eb.emission[c], t);
        }
        v.diffuse = std::min(ea.diffuse + (eb.diffuse - ea.diffuse) * t, lpyMostDiffuse(v.ambient));
        v.shininess = ea.shininess + (eb.shininess - ea.shininess) * t;
        v.transparency = ea.transparency + (eb.transparency - ea.transparency) * t;
        const std::vector<LpyMaterial> now = lpyMaterials(out);
        if (const LpyMaterial* m = at(now, k)) {
            for (int f = 0; f < 6; ++f) {
                const std::vector<LpyMaterial> again = lpyMaterials(out);
                out = setLpyMaterial(out, *at(again, k), LpyMaterial::Field(f), v);
            }
            (void)m;
            continue;
        }
        // A new one, after the last setMaterial line, indented as it is.
        size_t last = out.rfind("setMaterial(");
        if (last == std::string::npos) return error = "the model sets no material", "";
        const size_t lineStart = out.rfind('\n', last) + 1;
        size_t indentEnd = lineStart;
        while (indentEnd < out.size() && (out[indentEnd] == ' ' || out[indentEnd] == '\t')) ++indentEnd;
        const std::string indent = out.substr(lineStart, indentEnd - lineStart);
        size_t eol = out.find('\n', last);
        eol = eol == std::string::npos ? out.size() : eol + 1;
        const std::string name = "Color_" + std::to_string(k);
        auto colour = [](const std::array<int, 3>& c) {
            return "(" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]) + ")";
        };
        std::string lines;
        if (out.find("pgl.Material(") == std::string::npos) {  // the older form: Material and Color3 as the model imports them
            auto color3 = [&](const std::array<int, 3>& c) { return "Color3" + colour(c); };
            lines = indent + "context.turtle.setMaterial(" + std::to_string(k) + ",Material('" + name + "'," + color3(v.ambient) + "," +
                    formatted(v.diffuse) + "," + color3(v.specular) + "," + color3(v.emission) + "," + formatted(v.shininess) + "," +
                    formatted(v.transparency) + "))\n";
            if (eol == out.size() && !out.empty() && out.back() != '\n') lines = "\n" + lines;
            out.insert(eol, lines);
            continue;
        }
        lines = indent + name + " = pgl.Material(\"" + name + "\" , ambient = " + colour(v.ambient) + " , diffuse = " +
                            formatted(v.diffuse) + " , specular = " + colour(v.specular) + " , emission = " + colour(v.emission) +
                            " , shininess = " + formatted(v.shininess) + " , transparency = " + formatted(v.transparency) + " , )\n" +
                            indent + name + ".name = \"" + name + "\"\n" + indent + "context.turtle.setMaterial(" + std::to_string(k) + "," +
                            name + ")\n";
        if (eol == out.size() && !out.empty() && out.back() != '\n') lines = "\n" + lines;
        out.insert(eol, lines);
    }
    return out;
}

std::string setLpyTextureFile(std::string_view text, const LpyMaterial& m, std::string_view file, std::string& error) {
    if (m.texture.empty() || m.textureSpan[1] <= m.textureSpan[0] || m.textureSpan[1] > text.size())
        return error = "material " + std::to_string(m.index) + " names no image file", "";
    if (file.empty() || file.find_first_of("\n\r\\'") != std::string_view::npos)
        return error = "an image file's name, without quotes, backslashes or line breaks", "";
    std::string out(text);
    return out.replace(m.textureSpan[0], m.textureSpan[1] - m.textureSpan[0], "'" + std::string(file) + "'");
}

const char* lpyMaterialFieldName(LpyMaterial::Field f) { return kFields[int(f)]; }

std::optional<LpyMaterial::Field> lpyMaterialFieldNamed(std::string_view name) {
    for (int f = 0; f < 6; ++f)
        if (name == kFields[f]) return LpyMaterial::Field(f);
    return std::nullopt;
}

double lpyMostDiffuse(const std::array<int, 3>& ambient) {
    const int most = std::max({ambient[0], ambient[1], ambient[2]});
    return most > 0 ? 255.0 / most : 1e9;
}

double lpyEffectiveDiffuse(const LpyMaterial& m) { return std::min(m.diffuse, lpyMostDiffuse(m.ambient)); }

std::array<int, 3> lpyDiffuseColour(const LpyMaterial& m) {
    std::array<int, 3> c{};
    const double d = lpyEffectiveDiffuse(m);
    for (size_t i = 0; i < 3; ++i) {
        const double x = std::floor(m.ambient[i] * d);
        c[i] = std::isnan(x) ? 0 : int(std::clamp(x, 0.0, 255.0));  // any number the text holds: 0..255
    }
    return c;
}

}  // namespace sprout
