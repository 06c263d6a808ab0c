#pragma once
// What the environment programs share to read their specification files as their C does
// (fgets a line, strtok the keyword up to ':' or a tab, strtok the values, atof them), with a
// message at the file's line for what the C passes over in silence. Internal to cpfg_programs/.
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/environment/cpfg_programs/enviro_file.hpp"

namespace sprout::cpfgprog {

// Messages about one file.
struct Sink {
    std::vector<EnviroDiagnostic>* out = nullptr;
    std::string file;
    void warning(int line, std::string message) const;
    void error(int line, std::string message) const;
};

struct Token {
    std::string text;
    int col = 1;  // 1-based
};

// One line of a specification file: its keyword (strtok(line, "\t:")) and the rest of the line.
struct SpecLine {
    int number = 0;
    std::string keyword;
    std::string rest;  // after the keyword's delimiter
    int restCol = 1;
};
std::vector<SpecLine> specLines(std::string_view text);

// strtok(NULL, delims) to the line's end: the tokens of `rest`.
std::vector<Token> tokensOf(const SpecLine& line, std::string_view delims);

// atof: the number a token starts with (0 when none); a token that is not wholly a number gets
// a warning naming what was expected.
double numberOf(const Token& t, const SpecLine& line, const Sink& sink, const char* expected);

// An unknown keyword: a warning that lists the program's keywords (the program passes over it).
void unknownKeyword(const SpecLine& line, const std::vector<std::string>& keywords, const std::string& program,
                    const Sink& sink);

// A number taken as C's (int) cast does, within +-2e9 (a NaN or a bigger number gives the bound).
int toInt(double v);

// The number of cells of a grid of these sizes, or `cap + 1` as soon as it is over `cap` (whatever
// the sizes, nothing overflows); a size under 1 gives 0.
std::int64_t gridCells(std::initializer_list<int> sizes, std::int64_t cap);

// The programs, each made from its specification file's text (specName: its name, for messages;
// text: nullopt when it could not be read, with the message already given).
using FileReader = std::function<std::optional<std::string>(const std::string&, std::string&)>;
std::shared_ptr<EnvironmentProgram> makeHonda81(const std::string& specName, const std::string& text, const Sink& sink);
std::shared_ptr<EnvironmentProgram> makeEcosystem(const std::string& specName, const std::string& text, const Sink& sink);
std::shared_ptr<EnvironmentProgram> makeClover(const std::string& specName, const std::string& text, const Sink& sink,
                                               const FileReader& read);
std::shared_ptr<EnvironmentProgram> makeChiba(const std::string& specName, const std::string& text, const Sink& sink);
std::shared_ptr<EnvironmentProgram> makeObcheck(const std::string& specName, const std::string& text, const Sink& sink);

}  // namespace sprout::cpfgprog
