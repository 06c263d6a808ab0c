// A .e file (cpfg -e), read as VLab's comm library reads it (communication.c,
// ReadInEnvironmentalFile), and the program it names started as Sprout's own (enviro_file.hpp).
#include "core/environment/cpfg_programs/enviro_file.hpp"

#include <algorithm>
#include <filesystem>

#include "core/environment/cpfg_programs/spec_file.hpp"
#include "core/language/grammar.hpp"

namespace sprout {

const std::vector<std::string>& providedEnvironmentPrograms() {
    static const std::vector<std::string> names{"honda81", "ecosystem", "clover", "chiba", "obcheck"};
    return names;
}

namespace {

using cpfgprog::Sink;
using cpfgprog::SpecLine;

std::string listed(const std::vector<std::string>& names) {
    std::string out;
    for (size_t i = 0; i < names.size(); ++i) out += (i ? (i + 1 == names.size() ? " and " : ", ") : "") + names[i];
    return out;
}

// The words of the executable line: the program (its path left out) and its arguments, less the
// switches the comm library takes before them (-e FILE, -ext EXT, -k KEY, -host HOST).
struct Command {
    std::string program;
    std::vector<std::string> args;
};

Command commandOf(const std::string& line) {
    Command c;
    std::vector<std::string> words;
    for (size_t i = 0; i < line.size();) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const size_t b = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > b) words.push_back(line.substr(b, i - b));
    }
    if (words.empty()) return c;
    c.program = words[0].substr(words[0].rfind('/') == std::string::npos ? 0 : words[0].rfind('/') + 1);
    size_t k = 1;
    while (k < words.size() && words[k][0] == '-' && words[k].size() > 1 && std::string("ekhC").find(words[k][1]) != std::string::npos)
        k += 2;
    for (; k < words.size(); ++k) c.args.push_back(words[k]);
    return c;
}

}  // namespace

EnviroRead readEnviroText(const std::string& path, const std::string& text, const cpfgprog::FileReader& read,
                          const std::string& folder) {
    EnviroRead out;
    const Sink sink{&out.diagnostics, path};
    const std::vector<std::string> keywords{"communication type", "executable", "turtle position", "turtle heading",
                                            "turtle left", "turtle up", "turtle line width", "turtle scale factor",
                                            "when interpret", "verbose", "remote host", "strings only", "binary data",
                                            "interpreted modules", "following module"};
    TurtleFormats formats;
    std::string executable;
    int executableLine = 0;
    bool sendsQueries = true;
    for (const SpecLine& line : cpfgprog::specLines(text)) {
        const std::string& k = line.keyword;
        std::string rest = line.rest;
        auto format = [&](std::string& target, int n) {
            target = rest;
            std::string shown, why;
            const float probe[3] = {0, 0, 0};
            if (!formatTurtleValues(rest, probe, n, shown, &why)) {
                sink.warning(line.number, "'" + k + "': " + why + "; the program is not sent it");
                target.clear();
            }
        };
        if (k == "communication type") {
            const std::vector<cpfgprog::Token> t = cpfgprog::tokensOf(line, " \t:\n");
            const std::string type = t.empty() ? "" : t[0].text;
            if (type != "files" && type != "memory" && type != "pipes" && type != "sockets")
                sink.warning(line.number, "'communication type': expected files, memory, pipes or sockets, not '" + type +
                                              "' (cpfg uses pipes; in Sprout the program answers alike whichever)");
        } else if (k == "executable") {
            executable = rest;
            executableLine = line.number;
        } else if (k == "turtle position") {
            format(formats.position, 3);
        } else if (k == "turtle heading") {
            format(formats.heading, 3);
        } else if (k == "turtle left") {
            format(formats.left, 3);
        } else if (k == "turtle up") {
            format(formats.up, 3);
        } else if (k == "strings only" || k == "binary data") {
            const std::vector<cpfgprog::Token> t = cpfgprog::tokensOf(line, "\n ");
            if (!t.empty() && t[0].text == "on") sendsQueries = false;
        } else if (k == "turtle line width" || k == "turtle scale factor" || k == "when interpret" || k == "verbose" ||
                   k == "remote host" || k == "interpreted modules" || k == "following module") {
            // Read by cpfg for what Sprout's programs do not use (the modules' graphics, a host).
        } else {
            sink.warning(line.number, "cpfg's .e files have no setting '" + k + "' (cpfg passes over this line)");
        }
    }
    auto silent = [&] {
        auto p = std::make_shared<SilentProgram>();
        p->enviroFile = path;
        p->formats = formats;
        return p;
    };
    const Command command = commandOf(executable);
    if (command.program.empty()) {
        sink.warning(executableLine, "no 'executable: PROGRAM ARGUMENTS' line names the environment program: the "
                                     "environment is left out (cpfg leaves it out too) and ?E keeps its values");
        out.program = silent();
        return out;
    }
    const std::vector<std::string>& provided = providedEnvironmentPrograms();
    if (std::find(provided.begin(), provided.end(), command.program) == provided.end()) {
        sink.warning(executableLine, "the environment program '" + command.program + "' is not one Sprout provides (it provides " +
                                         listed(provided) + "): ?E keeps its values");
        out.program = silent();
        return out;
    }
    if (command.args.empty() || (command.program == "obcheck" && command.args.size() != 1)) {
        sink.warning(executableLine, command.program + " takes its specification file: 'executable: " + command.program +
                                         " FILE'" + (command.args.empty() ? "" : " (one file only)") + "; it does not start, and ?E keeps its values");
        out.program = silent();
        return out;
    }
    const std::string spec = command.args[0];
    std::string why;
    std::optional<std::string> specText = read(spec, why);
    if (!specText)
        sink.warning(executableLine, command.program + "'s specification file " + spec + " cannot be read" + (why.empty() ? "" : ": " + why) +
                                         "; it takes its defaults");
    const std::string specPath = (std::filesystem::path(folder.empty() ? std::filesystem::path(path).parent_path().string() : folder) / spec).string();
    const Sink specSink{&out.diagnostics, specPath};
    const std::string body = specText.value_or("");
    std::shared_ptr<EnvironmentProgram> p;
    if (command.program == "honda81") p = cpfgprog::makeHonda81(specPath, body, specSink);
    else if (command.program == "ecosystem") p = cpfgprog::makeEcosystem(specPath, body, specSink);
    else if (command.program == "clover") p = cpfgprog::makeClover(specPath, body, specSink, read);
    else if (command.program == "chiba") p = cpfgprog::makeChiba(specPath, body, specSink);
    else p = cpfgprog::makeObcheck(specPath, body, specSink);
    if (!p) {
        out.program = silent();
        return out;
    }
    p->name = command.program;
    p->enviroFile = path;
    p->formats = formats;
    p->sendsQueries = sendsQueries;
    out.program = std::move(p);
    return out;
}

EnviroRead readEnviroFile(const std::string& path, const std::string& folder) {
    const std::string own = std::filesystem::path(path).parent_path().string();
    std::string why;
    std::optional<std::string> text = includeFromFolder(own.empty() ? "." : own)(std::filesystem::path(path).filename().string(), why);
    if (!text) {
        EnviroRead out;
        out.diagnostics.push_back({path, {0, 0, "the environment file cannot be read" + (why.empty() ? "" : ": " + why), Severity::Error}});
        return out;
    }
    const std::string base = folder.empty() ? own : folder;
    return readEnviroText(path, *text, includeFromFolder(base.empty() ? "." : base), base);
}

}  // namespace sprout
