// The cpfg family's settings that name things (consider:, surface files, maximum depth:), and
// how #include and an environment's files are read beside the grammar (includeFromFolder).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/base/read_file.hpp"
#include "core/language/parser_impl.hpp"

namespace sprout::detail {

void Parser::setConsider(const SourceLine& line, std::string_view text) {
    std::vector<RawModule> mods;
    if (!tokenize(line, text, mods)) return;
    m_considerSet = true;
    for (const auto& m : mods) {
        if (m.hasParens) {
            m_sink.error(line, m.name, "list only module names after 'consider:', without parameters");
            return;
        }
        auto id = symbolFor(line, m.name, 0);
        if (!id) return;
        m_considered.push_back(m_g.alphabet[*id].nameId);
    }
}

void Parser::setSurface(const SourceLine& line, std::string_view text) {
    // cpfg's view-file line: `surface: NAME FILE.s [scale]` (the scale is not used: the
    // module's parameter scales the surface).
    std::istringstream words{std::string(text)};
    std::string name, file;
    if (!(words >> name >> file) || name.find_first_of("()[]~") != std::string::npos) {
        m_sink.error(line, text, "expected 'surface: NAME FILE.s', as in 'surface: s leaf.s'");
        return;
    }
    declareModules(line, "~" + name);
    if (!m_options.include) {
        m_sink.error(line, text, "surface '" + file + "' needs the grammar's folder: save the grammar beside it first");
        return;
    }
    std::string error;
    auto bytes = m_options.include(file, error);
    if (!bytes) {
        m_sink.error(line, text, "cannot read the surface '" + file + "': " + error);
        return;
    }
    auto surface = parseSurfaceFile(*bytes, error);
    if (!surface) {
        m_sink.error(line, text, "'" + file + "' is not a cpfg surface file: " + error);
        return;
    }
    m_g.surfaceFiles["~" + name] = std::make_shared<const SurfaceFile>(std::move(*surface));
}

void Parser::loadSurfaceFiles() {
    if (!m_options.include) return;
    for (const auto& [letter, file] : m_options.surfaces) {  // a VLab object's view file names them
        const std::string name = "~" + letter;
        if (m_g.surfaceFiles.count(name)) continue;
        std::string error;
        auto bytes = m_options.include(file, error);
        auto surface = bytes ? parseSurfaceFile(*bytes, error) : std::nullopt;
        if (!surface) {
            m_sink.add({0, 0, "the view file's surface '" + file + "' cannot be read (" + error + "): '" + name +
                                  "' is drawn as the built-in shape", Severity::Warning});
            continue;
        }
        m_g.surfaceFiles[name] = std::make_shared<const SurfaceFile>(std::move(*surface));
    }
    for (size_t s = 0; s < m_g.alphabet.size(); ++s) {
        const std::string& name = m_g.alphabet[SymbolId(s)].name;
        if (name.size() < 2 || name[0] != '~' || m_g.surfaceFiles.count(name)) continue;
        std::string error;
        auto bytes = m_options.include(name.substr(1) + ".s", error);
        if (!bytes) continue;  // no file: the built-in leaf and petal, or nothing
        auto surface = parseSurfaceFile(*bytes, error);
        if (!surface) {
            m_sink.add({0, 0, "'" + name.substr(1) + ".s' beside the grammar is not a cpfg surface file (" + error +
                                  "): '" + name + "' is drawn as the built-in shape", Severity::Warning});
            continue;
        }
        m_g.surfaceFiles[name] = std::make_shared<const SurfaceFile>(std::move(*surface));
    }
}

void Parser::setMaximumDepth(const SourceLine& line, std::string_view text) {
    auto v = constant(line, text);
    if (!v) return;
    // cpfg takes the expression's whole part (lsys_input.y: (int) Eval); homomorphisms of
    // thousands of levels (a leaf drawn segment by segment) are cpfg's own examples.
    if (m_options.tabContinues && *v >= 1) v = std::floor(*v);
    if (*v != std::floor(*v) || *v < 1 || *v > 100000) {
        m_sink.error(line, text, "maximum depth must be a whole number from 1 to 100000");
        return;
    }
    if (m_depthSection == Section::Interpretation) m_g.interpretationDepth = int(*v);
    else if (m_depthSection == Section::Decomposition) m_g.decompositionDepth = int(*v);
    else m_sink.warning(line, text, "'maximum depth:' belongs in the homomorphism or decomposition section: ignored here");
}

}  // namespace sprout::detail

namespace sprout {

IncludeReader includeFromFolder(std::string folder) {
    return [folder = std::move(folder)](const std::string& name, std::string& error) -> std::optional<std::string> {
        namespace fs = std::filesystem;
        std::error_code ec;
        fs::path rel(name);
        if (rel.is_absolute() || name.find("..") != std::string::npos) {
            error = "only files in the grammar's own folder can be included";
            return std::nullopt;
        }
        const fs::path base = fs::weakly_canonical(fs::path(folder.empty() ? "." : folder), ec);
        const fs::path target = fs::weakly_canonical(base / rel, ec);
        if (ec) {
            error = "no such file beside the grammar";
            return std::nullopt;
        }
        // A symbolic link may not lead out of the folder either.
        auto b = base.begin(), t = target.begin();
        for (; b != base.end() && t != target.end() && *b == *t; ++b, ++t) {}
        if (b != base.end()) {
            error = "it leads outside the grammar's folder";
            return std::nullopt;
        }
        if (!fs::is_regular_file(target, ec)) {
            error = "no such file beside the grammar";
            return std::nullopt;
        }
        if (fs::file_size(target, ec) > (4u << 20)) {
            error = "it is larger than 4 MB";
            return std::nullopt;
        }
        std::optional<std::string> text = readFile(target);
        if (!text) error = "it cannot be read";
        return text;
    };
}

}  // namespace sprout
