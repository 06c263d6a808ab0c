#pragma once
// What a source names, read: a file of any kind Sprout opens (FILE.l:System picks a Fractint
// system; Lparser and Fractint files become .lsys text, a PNG gives the grammar it carries),
// standard input ("-"), a VLab object's folder (the L-system its cpfg line runs), or a preset's name. Shared by openPlant (app/plant/open.hpp) and
// the Python module (python/), which runs L-Py models its own way.
#include <optional>
#include <string>
#include <vector>

#include "core/language/diagnostic.hpp"
#include "core/language/file_kind.hpp"

namespace sprout {

struct SourceText {
    std::string text;          // the grammar's text: .lsys, cpfg or L-Py as written, or translated
    FileKind kind = FileKind::Lsys;  // of `text`
    std::string displayName;   // for FILE:line:col messages
    std::string includePath;   // the file it came from (its folder: #include, files beside it), if any
    std::string dialect;       // "Lparser" or "Fractint" for a translated file, else empty
    std::vector<Diagnostic> diagnostics;  // the file's own, at its lines (named `diagnosticsName`)
    std::string diagnosticsName;
    std::string error;         // set when there is no grammar: the whole message, with the name
    // What the source says beside its grammar, each a whole line with its file: a VLab
    // object's files that are not read yet (warnings).
    std::vector<std::string> notes;
    bool ok() const { return error.empty() && !hasErrors(diagnostics); }
};

SourceText readSource(const std::string& source);

// The text of a file, or of its chunk `key` when it is a PNG written by Sprout (a forest scene
// or an iterated function system carried by its picture); nullopt when it cannot be read.
std::optional<std::string> readSourceOrChunk(const std::string& path, const char* key);

}  // namespace sprout
