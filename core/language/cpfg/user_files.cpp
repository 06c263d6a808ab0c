// cpfg's fopen and fscanf in statement blocks (user_files.hpp): the files read when the grammar
// is read, and fscanf's numbers read at the offset each file's hidden global keeps.
#include "core/language/cpfg/user_files.hpp"

#include <cctype>
#include <cstdio>
#include <string>
#include <vector>

namespace sprout {
namespace {

// The arguments of a call, split at the commas outside parentheses and strings.
std::vector<std::string_view> splitArguments(std::string_view args) {
    std::vector<std::string_view> out;
    int depth = 0;
    size_t from = 0;
    for (size_t i = 0; i <= args.size(); ++i) {
        const char c = i < args.size() ? args[i] : ',';
        if (c == '"') {
            for (++i; i < args.size() && args[i] != '"'; ++i)
                if (args[i] == '\\') ++i;
        } else if (c == '(' || c == '[') {
            ++depth;
        } else if (c == ')' || c == ']') {
            --depth;
        } else if (c == ',' && depth <= 0) {
            out.push_back(args.substr(from, i - from));
            from = i + 1;
        }
    }
    for (auto& a : out) {
        while (!a.empty() && isSpace(a.front())) a.remove_prefix(1);
        while (!a.empty() && isSpace(a.back())) a.remove_suffix(1);
    }
    return out;
}

// A string literal's text (C escapes \n \t \\ \" read), or nullopt when `a` is no string.
std::optional<std::string> stringLiteral(std::string_view a) {
    if (a.size() < 2 || a.front() != '"' || a.back() != '"') return std::nullopt;
    std::string out;
    for (size_t i = 1; i + 1 < a.size(); ++i) {
        if (a[i] == '\\' && i + 2 < a.size()) {
            const char e = a[++i];
            out += e == 'n' ? '\n' : e == 't' ? '\t' : e;
        } else {
            out += a[i];
        }
    }
    return out;
}

// fscanf's format cut after each conversion, each piece one sscanf call reads: its first
// character says into what ('f' a double, from %lf; 'd' an int; '-' nothing: the text after
// the last conversion). Empty `error` when it reads numbers only.
std::vector<std::string> formatPieces(const std::string& format, std::string& error, int& conversions) {
    std::vector<std::string> pieces;
    std::string piece;
    conversions = 0;
    for (size_t i = 0; i < format.size(); ++i) {
        if (format[i] != '%') {
            piece += format[i];
            continue;
        }
        if (i + 1 < format.size() && format[i + 1] == '%') {
            piece += "%%";
            ++i;
            continue;
        }
        size_t j = i + 1;
        const bool skip = j < format.size() && format[j] == '*';
        if (skip) ++j;
        std::string width;
        while (j < format.size() && std::isdigit(static_cast<unsigned char>(format[j])) && width.size() < 6) width += format[j++];
        while (j < format.size() && (format[j] == 'l' || format[j] == 'L' || format[j] == 'h')) ++j;
        const char c = j < format.size() ? format[j] : '\0';
        const bool real = c != '\0' && std::string_view("fFeEgGaA").find(c) != std::string_view::npos;
        if (!real && c != 'd' && c != 'i') {
            error = "fscanf reads numbers into variables: its conversions are %f, %g, %e or %d, not '" +
                    format.substr(i, std::min(j + 1, format.size()) - i) + "'";
            return {};
        }
        piece += std::string("%") + (skip ? "*" : "") + width + (real ? "lf" : "d");
        if (!skip) {
            ++conversions;
            pieces.push_back((real ? "f" : "d") + piece);
            piece.clear();
        }
        i = j;
    }
    if (!piece.empty()) pieces.push_back("-" + piece);
    return pieces;
}

}  // namespace

void runOpen(const Statement& s, double* slots) {
    const UserFile* f = s.files && s.file < s.files->size() ? &(*s.files)[s.file] : nullptr;
    // cpfg's fopen gives -1 for a file it cannot open; Sprout's index of the others.
    if (s.size == 1) slots[s.slot] = f && (f->readable || f->mode.find('r') == std::string::npos) ? double(s.file) : -1.0;
    if (f && f->readable) slots[f->cursor] = 0;
}

void runScan(const Statement& s, double* slots, Rng& rng) {
    const double id = s.expr.eval(slots, rng);
    int count = -1;  // C's EOF: no file, or nothing left
    if (s.files && id >= 0 && id < double(s.files->size()) && (*s.files)[size_t(id)].readable) {
        const UserFile& f = (*s.files)[size_t(id)];
        double& cursor = slots[f.cursor];
        size_t at = cursor > 0 && cursor < double(f.text.size()) ? size_t(cursor) : cursor > 0 ? f.text.size() : 0;
        size_t target = 0;
        for (const std::string& piece : s.pieces) {
            // A window of the text from `at` (sscanf measures the whole string it reads).
            const std::string window = f.text.substr(at, 4096);
            const std::string format = piece.substr(1) + "%n";
            int used = -1, whole = 0, n = 0;
            double number = 0;
            const char into = target < s.targets.size() ? piece[0] : '-';
            if (into == 'f') n = std::sscanf(window.c_str(), format.c_str(), &number, &used);
            else if (into == 'd') n = std::sscanf(window.c_str(), format.c_str(), &whole, &used);
            else n = std::sscanf(window.c_str(), format.c_str(), &used);
            if (used < 0) {  // the piece did not match all through: C's fscanf stops here
                if (n == 1 && into != '-') {  // its number read, the text after it not
                    slots[s.targets[target++]] = into == 'd' ? double(whole) : number;
                    count = count < 0 ? 1 : count + 1;
                } else if (n != EOF && count < 0) {
                    count = 0;
                }
                break;
            }
            at += size_t(used);
            if (into != '-') {
                slots[s.targets[target++]] = into == 'd' ? double(whole) : number;
                count = count < 0 ? 1 : count + 1;
            } else if (count < 0) {
                count = 0;
            }
        }
        cursor = double(at);
    }
    if (s.size == 1) slots[s.slot] = count;
}

namespace detail {

bool noEffectCall(std::string_view name) {
    return name == "printf" || name == "fprintf" || name == "fflush" || name == "fclose" || name == "stop" ||
           name == "Display" || name == "play";
}

bool compileFopen(FileCalls& files, DiagnosticSink& sink, const SourceLine& line, std::string_view args, Statement& s) {
    const std::vector<std::string_view> a = splitArguments(args);
    std::optional<std::string> name = a.size() == 2 ? stringLiteral(a[0]) : std::nullopt;
    std::optional<std::string> mode = a.size() == 2 ? stringLiteral(a[1]) : std::nullopt;
    if (!name || !mode || name->empty() || mode->empty()) {
        sink.error(line, args, "expected a file's name and its mode in quotes, as in 'fp = fopen(\"data.txt\", \"r\");'");
        return false;
    }
    if (!files.g.userFiles) files.g.userFiles = std::make_shared<std::vector<UserFile>>();
    if (files.g.userFiles->size() >= 64) {
        sink.error(line, args, "too many fopen calls (the limit is 64)");
        return false;
    }
    UserFile f;
    f.name = *name;
    f.mode = *mode;
    if (mode->find('r') != std::string::npos) {
        std::string error;
        std::optional<std::string> text;
        if (files.include) text = files.include(*name, error);
        else error = "the text has no folder to read it from";
        if (text) {
            f.readable = true;
            f.text = std::move(*text);
            f.cursor = std::uint16_t(kGlobalSlot + files.g.globals.size());
            files.g.globals.emplace_back();  // never a name: fscanf's offset
            files.g.globalInit.push_back(0);
        } else {
            sink.warning(line, a[0], "fopen cannot open '" + *name + "' (" + error + "): it gives -1, as cpfg's does");
        }
    } else {
        sink.warning(line, a[0], "Sprout does not write files from a model: what fprintf sends to '" + *name +
                                     "' is not written");
    }
    s.kind = Statement::Kind::Open;
    s.file = std::uint16_t(files.g.userFiles->size());
    files.g.userFiles->push_back(std::move(f));
    s.files = files.g.userFiles;
    return true;
}

bool compileFscanf(FileCalls& files, DiagnosticSink& sink, const SourceLine& line, std::string_view args,
                   const ExprScope& scope, const std::function<std::optional<std::uint16_t>(std::string_view)>& slotOf,
                   Statement& s) {
    const std::vector<std::string_view> a = splitArguments(args);
    std::optional<std::string> format = a.size() >= 2 ? stringLiteral(a[1]) : std::nullopt;
    if (!format) {
        sink.error(line, args, "expected a file, a format in quotes and the variables, as in 'fscanf(fp, \"%f %f\", &a, &b);'");
        return false;
    }
    std::string error;
    int conversions = 0;
    s.pieces = formatPieces(*format, error, conversions);
    if (!error.empty()) {
        sink.error(line, a[1], error);
        return false;
    }
    if (conversions != int(a.size()) - 2 || conversions > 16) {
        sink.error(line, a[1], "the format reads " + std::to_string(conversions) + " number" + (conversions == 1 ? "" : "s") +
                                   " but " + std::to_string(a.size() - 2) + " variable" + (a.size() == 3 ? " is" : "s are") +
                                   " given" + (conversions > 16 ? " (at most 16)" : ""));
        return false;
    }
    auto fileExpr = compileExpr(a[0], line, scope, sink);
    if (!fileExpr) return false;
    s.expr = std::move(*fileExpr);
    for (size_t k = 2; k < a.size(); ++k) {
        std::string_view v = a[k];
        if (v.empty() || v.front() != '&') {
            sink.error(line, v.empty() ? args : v, "fscanf reads into a variable written '&name'");
            return false;
        }
        v.remove_prefix(1);
        while (!v.empty() && isSpace(v.front())) v.remove_prefix(1);
        std::optional<std::uint16_t> slot = slotOf(v);
        if (!slot) {
            sink.error(line, a[k], "fscanf reads into a variable ('&x'), not into '" + std::string(v) + "'");
            return false;
        }
        s.targets.push_back(*slot);
    }
    s.kind = Statement::Kind::Scan;
    if (!files.g.userFiles) files.g.userFiles = std::make_shared<std::vector<UserFile>>();
    s.files = files.g.userFiles;
    return true;
}

}  // namespace detail
}  // namespace sprout
