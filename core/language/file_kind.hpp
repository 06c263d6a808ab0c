#pragma once
// What a file is, decided from its content (the extension is only a hint): every entry point
// (the CLI's expand / render / export, the viewer's command line, Open, drop and reload, PNG
// import, the worker) asks this one function instead of sniffing text on its own.
#include <string>
#include <string_view>

#include "core/language/grammar.hpp"

namespace sprout {

enum class FileKind {
    Lsys,      // Sprout's own grammar language
    Cpfg,      // the cpfg / lpfg family: Lsystem:, derivation length:, -->, /* */ ...
    Lpy,       // an L-Py model (.lpy): Python with L-system sections (lpy/ runs it; without
               // Python it is read as the cpfg family)
    Lparser,   // Lparser 5 .ls
    Fractint,  // Fractint .l (several named systems)
    Ifs,       // iterated function system
    Forest,    // forest scene
    Png,       // a picture; Sprout's carry their grammar in a text chunk
};

// `path` may be empty (text typed into the editor); `bytes` is the whole file.
FileKind detectFileKind(std::string_view path, std::string_view bytes);

// How to parse a text of `kind` read from `path` (empty: typed, no folder): the cpfg
// dialect for the cpfg family, with #include reading files beside `path`.
ParseOptions parseOptionsFor(FileKind kind, const std::string& path);

// Parses a grammar text as what detectFileKind says it is (.lsys or cpfg family): presets,
// forest species and tests use it, so a cpfg-family text works wherever a .lsys one does.
ParseResult parseDetected(std::string_view text, const std::string& path = {});

// "cpfg", "Lparser", ... for messages.
const char* fileKindName(FileKind kind);

// True when a text is an L-Py model: an `Axiom:` line and a `production:` line or L-Py's
// Python (`def`, `import`, `nproduce`, `__initialiseContext__`), and no cpfg `Lsystem:` line.
bool looksLikeLpy(std::string_view text);

// The cpfg family: cpfg, lpfg and L-Py read as cpfg (parseOptionsFor gives the cpfg dialect).
inline bool cpfgFamily(FileKind kind) { return kind == FileKind::Cpfg || kind == FileKind::Lpy; }

// True when the text carries marks only the cpfg / L-Py family uses (an `Lsystem:` or
// `derivation length:` line, `endlsystem`, `/* */` comments, `#include`, a `decomposition`
// section, L-Py's `produce`).
bool looksLikeCpfg(std::string_view text);

// An .ifs text: its first line that is not a comment is seven numbers (no '->').
bool looksLikeIfs(std::string_view text);

// A .forest scene: its first line that is not blank or a comment is `scene: forest`.
bool isForestScene(std::string_view text);

}  // namespace sprout
