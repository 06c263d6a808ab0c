#pragma once
// Importers: grammar files of other tools translated into Sprout's .lsys text, so that the
// result can be read, edited and saved like any grammar.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/language/diagnostic.hpp"
#include "core/language/file_kind.hpp"

namespace sprout {

struct ImportResult {
    std::string text;                      // the text to edit: .lsys, cpfg as written, .ifs or .forest
    std::vector<Diagnostic> diagnostics;   // problems in the source, with its line numbers
    FileKind kind = FileKind::Lsys;        // of `text`: Lsys, Cpfg, Ifs or Forest (never a translated kind)
    FileKind source = FileKind::Lsys;      // what the file itself was (Lparser, Fractint, Png ...)
    bool ok() const { return !hasErrors(diagnostics); }
};

// Lparser 5 (Laurens Lapré): the keyword format (`recursion`, `angle`, `thickness`,
// `min_thickness`, `shape`, `switch_yz`, `color i r g b`, `axiom`, `rule X = ...`) and the
// older positional one (recursion, angle, thickness, axiom, then `X=...` rules, `@`).
ImportResult importLparser(std::string_view source, std::string_view name);

// One system of a Fractint .l file (`Name { Angle n  Axiom ...  X=... }`).
struct FractintSystem {
    std::string name;
    int line = 0;
};
std::vector<FractintSystem> listFractint(std::string_view source);
ImportResult importFractint(std::string_view source, std::string_view system);

// The grammar a PNG written by Sprout carries (`sprout render`, viewer screenshots): the text
// of its "lsys", "ifs" or "forest" chunk. An error when the PNG holds none.
ImportResult importPng(std::string_view png);
// One uncompressed tEXt / iTXt chunk by keyword; nullopt with `error` set when the file is not
// a PNG or is damaged, nullopt with an empty `error` when the chunk is absent.
std::optional<std::string> pngTextChunk(std::string_view png, std::string_view keyword, std::string& error);

// Any file Sprout opens, by what detectFileKind() says it is: Lparser and Fractint files
// (`system` picks one, default the first) are translated to .lsys; a PNG gives the text it
// carries; .lsys, cpfg-family, .ifs and .forest texts are returned as they are written.
ImportResult importFile(std::string_view path, std::string_view source, std::string_view system = {});

}  // namespace sprout
