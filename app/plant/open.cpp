#include "app/plant/open.hpp"

#include <sys/stat.h>

#include "app/plant/presets.hpp"
#include "app/plant/source.hpp"
#include "app/plant/vlab_view.hpp"
#include "app/plant/vlab_curves.hpp"
#include "app/plant/vlab_environment.hpp"
#include "core/base/read_file.hpp"
#include "core/language/import/import.hpp"
#include "lpy/lpy.hpp"

namespace sprout {

FileKind sourceKind(const std::string& source) {
    struct stat st{};
    if (source != "-" && ::stat(source.c_str(), &st) == 0) {
        auto bytes = readFile(source);
        if (!bytes) return FileKind::Lsys;  // openPlant says why
        ImportResult r = importFile(source, *bytes);
        return r.ok() ? r.kind : FileKind::Lsys;
    }
    if (auto preset = presetText(source)) return detectFileKind("", *preset);
    return FileKind::Lsys;
}

OpenedText openText(const std::string& text, FileKind kind, const std::string& path, const lpy::RunOptions& lpyOptions) {
    OpenedText out;
    if (kind == FileKind::Lpy && lpy::pythonAvailable()) {
        lpy::RunOptions ro = lpyOptions;
        ro.path = path;
        out.model = std::make_shared<lpy::Model>(lpy::runModel(text, ro));
        out.grammar = out.model->drawable;
        out.diagnostics = out.model->diagnostics;
        return out;
    }
    ParseOptions po = parseOptionsFor(kind, path);
    if (po.cpfg && !path.empty()) {
        po.environmentProgram = objectEnvironment(path).program;  // a VLab object's -e
        readVlabCurves(path, po);                                 // its functions, contours, surfaces
    }
    ParseResult r = parse(text, po);
    out.grammar = std::move(r.grammar);
    // A VLab object's L-system draws as its view, colours and window say (vlab_view.hpp).
    if (out.grammar && cpfgFamily(kind)) {
        Settings settings = out.grammar->settings;
        if (applyVlabObjectOf(path, settings)) {
            auto g = std::make_shared<Grammar>(*out.grammar);
            g->settings = std::move(settings);
            out.grammar = std::move(g);
        }
    }
    out.diagnostics = std::move(r.diagnostics);
    return out;
}

std::optional<LoadedGrammar> openPlant(const std::string& source, const LoadOptions& options, const Report& report) {
    SourceText read = readSource(source);
    for (const std::string& note : read.notes) report(note);
    for (const auto& d : read.diagnostics) report(formatDiagnostic(d, read.diagnosticsName));
    if (!read.error.empty()) report(read.error);
    if (!read.ok()) return std::nullopt;
    LoadedGrammar out;
    out.displayName = std::move(read.displayName);
    out.kind = read.kind;
    out.dialect = std::move(read.dialect);
    std::string text = std::move(read.text), includePath = std::move(read.includePath);
    if (out.kind == FileKind::Lpy && lpy::pythonAvailable()) {
        // An L-Py model is a Python program: run as `python3 FILE` would run it.
        if (!options.python) {
            report(out.displayName + ": an L-Py model runs Python; --no-python refuses to run it");
            return std::nullopt;
        }
        lpy::RunOptions ro;
        ro.steps = options.steps;
        ro.keepSteps = options.keepSteps;
        if (options.maxModules) ro.maxModules = std::size_t(options.maxModules);
        if (options.maxBytes) ro.maxBytes = options.maxBytes;
        OpenedText opened = openText(text, out.kind, includePath, ro);
        for (const auto& d : opened.diagnostics) report(formatDiagnostic(d, out.displayName));
        if (!opened.ok()) return std::nullopt;
        out.grammar = opened.grammar;
        out.derived = std::move(opened.model->derived);
        out.steps = std::move(opened.model->steps);
        out.ranPython = true;
        out.dialect = "L-Py";
        out.text = std::move(text);
        return out;
    }
    OpenedText opened = openText(text, out.kind, includePath);
    for (const auto& d : opened.diagnostics) report(formatDiagnostic(d, out.displayName));
    if (!opened.ok()) return std::nullopt;
    out.grammar = opened.grammar;
    if (out.dialect.empty()) out.dialect = opened.grammar->dialect;
    out.text = std::move(text);
    return out;
}

// A forest scene: its species are presets or files beside the scene file.
}  // namespace sprout
