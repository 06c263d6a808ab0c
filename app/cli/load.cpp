#include "app/cli/load.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <sys/stat.h>

#include "app/presets.hpp"
#include "app/source.hpp"
#include "core/language/import/import.hpp"
#include "lpy/lpy.hpp"

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
    SourceText read = readSource(source);
    for (const auto& d : read.diagnostics) std::cerr << formatDiagnostic(d, read.diagnosticsName) << "\n";
    if (!read.error.empty()) std::cerr << read.error << "\n";
    if (!read.ok()) return std::nullopt;
    LoadedGrammar out;
    out.displayName = std::move(read.displayName);
    out.kind = read.kind;
    out.dialect = std::move(read.dialect);
    std::string text = std::move(read.text), includePath = std::move(read.includePath);
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
        if (options.maxModules) ro.maxModules = std::size_t(options.maxModules);
        if (options.maxBytes) ro.maxBytes = options.maxBytes;
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
