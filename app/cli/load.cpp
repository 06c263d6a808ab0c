#include "app/cli/load.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <sys/stat.h>

#include "app/presets.hpp"
#include "core/language/import/import.hpp"
#include "lpy/host.hpp"

namespace sprout::cli {
namespace {

std::optional<std::string> readFile(const std::string& path, std::string& error) {
    struct stat st{};
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
        error = "is a directory, not a grammar file";
        return std::nullopt;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = "cannot be opened";
        return std::nullopt;
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

FileKind sourceKind(const std::string& source) {
    struct stat st{};
    if (source != "-" && ::stat(source.c_str(), &st) == 0) {
        std::string error;
        auto bytes = readFile(source, error);
        if (!bytes) return FileKind::Lsys;  // loadGrammar says why
        ImportResult r = importFile(source, *bytes);
        return r.ok() ? r.kind : FileKind::Lsys;
    }
    if (auto preset = presetText(source)) return detectFileKind("", *preset);
    return FileKind::Lsys;
}

std::optional<LoadedGrammar> loadGrammar(const std::string& source, const LoadOptions& options) {
    std::string text, error, includePath;
    LoadedGrammar out;
    out.displayName = source;
    struct stat st{};
    // FILE.l:System picks one system of a Fractint file.
    std::string path = source, system;
    if (::stat(source.c_str(), &st) != 0) {
        if (size_t colon = source.rfind(':'); colon != std::string::npos && colon > 0) {
            struct stat st2{};
            if (::stat(source.substr(0, colon).c_str(), &st2) == 0) {
                path = source.substr(0, colon);
                system = source.substr(colon + 1);
            }
        }
    }
    if (source == "-") {
        text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
        out.displayName = "<stdin>";
        out.kind = detectFileKind("", text);
    } else if (::stat(path.c_str(), &st) == 0) {
        auto t = readFile(path, error);
        if (!t) {
            std::cerr << path << ": " << error << "\n";
            return std::nullopt;
        }
        // What the file is, from its content: Lparser .ls and Fractint .l files are
        // translated to .lsys; cpfg-family files are read as they are written.
        ImportResult imported = importFile(path, *t, system);
        for (const auto& d : imported.diagnostics) std::cerr << formatDiagnostic(d, path) << "\n";
        if (!imported.ok()) return std::nullopt;
        if (imported.kind == FileKind::Ifs || imported.kind == FileKind::Forest) {
            std::cerr << path << ": holds " << (imported.kind == FileKind::Ifs ? "an iterated function system" : "a forest scene")
                      << ", not one grammar: `sprout render` draws it\n";
            return std::nullopt;
        }
        if (imported.text != *t) out.displayName = path + " (as .lsys)";
        text = std::move(imported.text);
        out.kind = imported.kind;
        if (imported.source == FileKind::Lparser) out.dialect = "Lparser";
        if (imported.source == FileKind::Fractint) out.dialect = "Fractint";
        if (imported.source != FileKind::Png) includePath = path;
    } else if (auto preset = presetText(source)) {
        text = std::string(*preset);
        out.kind = detectFileKind("", text);
        out.displayName = std::string(source) + (source.find('.') != std::string::npos ? "" : out.kind == FileKind::Lpy ? ".lpy" : out.kind == FileKind::Cpfg ? ".l" : ".lsys");
    } else {
        std::cerr << source << ": no such file or preset; presets are:";
        for (const auto& n : presetNames()) std::cerr << " " << n;
        std::cerr << "\n";
        return std::nullopt;
    }
    if (out.kind == FileKind::Lpy && lpy::pythonAvailable()) {
        // An L-Py model is a Python program: run as `python3 FILE` would run it.
        if (!options.python) {
            std::cerr << out.displayName << ": an L-Py model runs Python; --no-python refuses to run it\n";
            return std::nullopt;
        }
        lpy::RunOptions ro;
        ro.path = includePath;
        ro.steps = options.steps;
        ro.keepSteps = options.keepSteps;
        lpy::Model model = lpy::runModel(text, ro);
        for (const auto& d : model.diagnostics) std::cerr << formatDiagnostic(d, out.displayName) << "\n";
        if (!model.ok()) return std::nullopt;
        out.grammar = model.drawable;
        out.derived = std::move(model.derived);
        out.steps = std::move(model.steps);
        out.ranPython = true;
        out.dialect = "L-Py";
        out.text = std::move(text);
        return out;
    }
    ParseResult r = parse(text, parseOptionsFor(out.kind, includePath));
    for (const auto& d : r.diagnostics) std::cerr << formatDiagnostic(d, out.displayName) << "\n";
    if (!r.ok()) return std::nullopt;
    out.grammar = r.grammar;
    if (out.dialect.empty()) out.dialect = r.grammar->dialect;
    out.text = std::move(text);
    return out;
}

}  // namespace sprout::cli
