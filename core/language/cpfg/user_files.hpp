#pragma once
// cpfg's file functions in statement blocks (the CPFG manual's "Input and output functions"):
// `fp = fopen("data.txt", "r");`, `fscanf(fp, "%f %f", &a, &b);`, and fprintf, fflush and
// fclose. A file opened for reading is read whole from the model's folder when the grammar is
// read (ParseOptions::include, which keeps to that folder); fscanf reads numbers from it at
// the offset a hidden global keeps, so each derivation reads it afresh from its fopen. What a
// model writes is not written: Sprout derives on every edit, and a model's text does not get
// to write files on the user's disk (a warning at the fopen says so).
//
// Every variable is a number, as in cpfg: fscanf's conversions are %f, %g, %e (read as
// doubles, with or without `l`) and %d, %i (whole numbers); a string or character conversion
// is an error at the line. (cpfg 6 built for 64 bits stores %f's float into a double's low
// half, so that its %f reads 0 where the manual and %lf read the number; Sprout reads it.)
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>

#include "core/language/grammar.hpp"

namespace sprout {

// Run by the derivation's statement blocks (core/derive/step_rewriter.cpp).
void runOpen(const Statement& s, double* slots);
void runScan(const Statement& s, double* slots, Rng& rng);

namespace detail {

// What the statement parser needs to open files: the grammar that keeps them and its hidden
// globals, and the reader of the model's folder (null: text with no folder).
struct FileCalls {
    Grammar& g;
    const IncludeReader& include;
};

// `fopen("name", "mode")`'s arguments (the text inside its parentheses) into `s` (kind Open).
bool compileFopen(FileCalls& files, DiagnosticSink& sink, const SourceLine& line, std::string_view args, Statement& s);
// `fscanf(fp, "format", &a, ...)`'s arguments into `s` (kind Scan); `slotOf` finds the slot
// of a variable the block may assign.
bool compileFscanf(FileCalls& files, DiagnosticSink& sink, const SourceLine& line, std::string_view args,
                   const ExprScope& scope, const std::function<std::optional<std::uint16_t>(std::string_view)>& slotOf,
                   Statement& s);
// cpfg's calls that do nothing in Sprout's derivation: printf, fprintf, fflush, fclose (the
// messages and files of cpfg's run), stop, Display, play (its animation window and sound).
bool noEffectCall(std::string_view name);

}  // namespace detail
}  // namespace sprout
