#include "app/plant/source.hpp"

#include <iostream>
#include <iterator>
#include <sys/stat.h>

#include "app/plant/presets.hpp"
#include "app/plant/vlab_curves.hpp"
#include "app/plant/vlab_environment.hpp"
#include "app/plant/vlab_object.hpp"
#include "app/plant/vlab_view.hpp"
#include "core/base/read_file.hpp"
#include "core/language/import/import.hpp"

namespace sprout {

SourceText readSource(const std::string& source) {
    SourceText out;
    out.displayName = source;
    struct stat st{};
    // FILE.l:System picks one system of a Fractint file.
    std::string path = source, system;
    if (::stat(source.c_str(), &st) != 0)
        if (size_t colon = source.rfind(':'); colon != std::string::npos && colon > 0 && ::stat(source.substr(0, colon).c_str(), &st) == 0) {
            path = source.substr(0, colon);
            system = source.substr(colon + 1);
        }
    if (source == "-") {
        out.text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
        out.displayName = "<stdin>";
        out.kind = detectFileKind("", out.text);
    } else if (::stat(path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) {
            // A VLab object opens with the L-system its cpfg line runs (vlab_object.hpp).
            std::optional<VlabObject> object = readVlabObject(path);
            if (!object) {
                out.error = path + ": is a directory, not a grammar file";
                return out;
            }
            if (hasErrors(object->diagnostics)) {
                out.diagnostics = std::move(object->diagnostics);
                out.diagnosticsName = object->specifications;
                return out;
            }
            for (const Diagnostic& d : object->diagnostics) out.notes.push_back(formatDiagnostic(d, object->specifications));
            for (std::string& note : readVlabPicture(*object).notes) out.notes.push_back(std::move(note));
            path = object->lsystem;
            out.displayName = path;
        }
        // A VLab object's environment (-e): its messages here; openText gives the parser its program.
        if (ObjectEnvironment env = objectEnvironment(path); env.failed) {
            for (size_t k = 0; k + 1 < env.messages.size(); ++k) out.notes.push_back(env.messages[k]);
            out.error = env.messages.back();
            return out;
        } else {
            for (std::string& m : env.messages) out.notes.push_back(std::move(m));
        }
        {  // its functions', contours' and surfaces' problems (openText reads them for the parse)
            ParseOptions scratch;
            for (std::string& m : readVlabCurves(path, scratch).problems) out.notes.push_back(std::move(m));
        }
        std::optional<std::string> bytes = readFile(path);
        if (!bytes) {
            out.error = path + ": cannot be opened";
            return out;
        }
        const std::string t = std::move(*bytes);
        // What the file is, from its content: Lparser .ls and Fractint .l files are
        // translated to .lsys; cpfg-family files are read as they are written.
        ImportResult imported = importFile(path, t, system);
        out.diagnostics = std::move(imported.diagnostics);
        out.diagnosticsName = path;
        if (hasErrors(out.diagnostics)) return out;
        if (imported.kind == FileKind::Ifs || imported.kind == FileKind::Forest) {
            out.error = path + ": holds " + (imported.kind == FileKind::Ifs ? "an iterated function system" : "a forest scene") +
                        ", not one grammar: `sprout render` draws it";
            return out;
        }
        if (imported.text != t) out.displayName = path + " (as .lsys)";
        out.text = std::move(imported.text);
        out.kind = imported.kind;
        if (imported.source == FileKind::Lparser) out.dialect = "Lparser";
        if (imported.source == FileKind::Fractint) out.dialect = "Fractint";
        if (imported.source != FileKind::Png) out.includePath = path;
    } else if (auto preset = presetText(source)) {
        out.text = std::string(*preset);
        out.kind = detectFileKind("", out.text);
        out.displayName = source + (source.find('.') != std::string::npos ? "" : out.kind == FileKind::Lpy ? ".lpy" : out.kind == FileKind::Cpfg ? ".l" : ".lsys");
    } else {
        out.error = source + ": no such file or preset; presets are:";
        for (const auto& n : presetNames()) out.error += " " + n;
    }
    return out;
}

std::optional<std::string> readSourceOrChunk(const std::string& path, const char* key) {
    std::optional<std::string> text = readFile(path);
    if (!text || detectFileKind(path, *text) != FileKind::Png) return text;
    std::string error;
    return pngTextChunk(*text, key, error);
}

}  // namespace sprout
