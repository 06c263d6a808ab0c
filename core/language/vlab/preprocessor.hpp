#pragma once
// The C preprocessor as cpfg runs it over a VLab file before reading its words (cpfg's
// PreprocessFile: `preproc FILE`, or vlabcpp): comments (/* */, and // as cpp reads them)
// blanked, lines ending in '\' joined, `#define NAME text` and `#define NAME(a, b) text`
// put in place (no space added around them: `-STEP` is `-35`, as preproc gives it),
// `#undef`, `#include "file"` (or <file>), and `#ifdef`, `#ifndef`, `#if` of a number or
// `defined NAME`, `#elif`, `#else`, `#endif`. What comes out is the file's words, each with
// the file, line and column it came from (a macro's words: where its name was), so that a
// reader's messages point into the file as written. Problems are messages at their line;
// nothing in a file can make it loop or grow without bound (includes nest 16 deep, a line's
// expansion stops at 1 MB). Never throws.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/language/diagnostic.hpp"

namespace sprout::vlab {

struct PreprocessedWord {
    std::string text;
    std::uint16_t file = 0;  // into Preprocessed::files
    int line = 0, col = 0;   // 1-based, in that file as written
};

struct Preprocessed {
    std::vector<PreprocessedWord> words;
    std::vector<std::string> files;  // [0] the file itself, then the files it includes
    struct Problem {
        std::uint16_t file = 0;
        Diagnostic diagnostic;
    };
    std::vector<Problem> problems;  // at most 64, in the order found
};

// Reads an #include's file: `name` as written, included from the file `from` (a name in
// Preprocessed::files); fills `path` with the name to report it by. nullopt, with `error`
// saying why, when it cannot be read.
using IncludeReader = std::function<std::optional<std::string>(const std::string& from, const std::string& name, std::string& path,
                                                               std::string& error)>;

// The words of `text` (the file `file`) as cpfg reads them after its preprocessor. Without an
// `include` reader, an #include is an error naming the file.
Preprocessed preprocessWords(std::string_view text, const std::string& file, const IncludeReader& include = {});

}  // namespace sprout::vlab
