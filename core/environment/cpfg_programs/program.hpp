#pragma once
// cpfg's environment programs (`cpfg -e FILE.e`), provided natively: what each one answers the
// ?E modules, with the communication semantics of VLab's comm library (libs/comm): after each
// derivation step the string is interpreted, each ?E is sent with the turtle's state as the .e
// file's formats print it, the program answers some of its parameters, and the next step's
// productions see them. The .e file is read by readEnviroFile (enviro_file.hpp); the programs
// are honda81.cpp, ecosystem.cpp, clover.cpp and obcheck.cpp beside this file.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/language/environment_spec.hpp"

namespace sprout {

// One turtle value as the program receives it: the .e file's format printed it (`turtle
// position: %.4f %.4f %.4f`) and the program read back the numbers (comm_slave.c, CSGetData).
struct TurtleField {
    std::array<float, 3> v{0.0f, 0.0f, 0.0f};
    int count = 0;  // the numbers the format sends (0: the .e file does not send it)
};

// One ?E as the program gets it, and its answer.
struct ProgramQuery {
    std::vector<float> params;  // the ?E's parameters, as sent (printed with %g, read back)
    TurtleField position, heading, left, up;
    // The answer: the parameters the program sets (`set`), in order; the others keep their
    // values. Empty: no answer.
    std::vector<float> answer;
    std::vector<bool> set;
    void reply(std::vector<float> values) {
        answer = std::move(values);
        set.assign(answer.size(), true);
    }
};

// One derivation's run of a program: programs keep state from step to step (clover's leaves,
// obcheck's last turtle position), as the program's process does while cpfg runs.
class ProgramRun {
public:
    virtual ~ProgramRun() = default;
    // One interpretation pass: every ?E of the string, in the order the turtle meets them.
    virtual void pass(std::vector<ProgramQuery>& queries) = 0;
};

// The turtle values a .e file sends, each as a printf format of its numbers (empty: not sent).
struct TurtleFormats {
    std::string position, heading, left, up;
};

// A program named by a .e file, with its specification read.
class EnvironmentProgram {
public:
    virtual ~EnvironmentProgram() = default;
    std::string name;           // as the .e file names it ("honda81", "obcheck")
    std::string enviroFile;     // the .e file's path
    TurtleFormats formats;
    bool sendsQueries = true;   // false: `strings only: on` (the program gets no ?E)
    // When cpfg asks it: false (cpfg's default, `environment display: after` in the view file)
    // as each step begins, of the string before it, so a step's string shows its ?E unanswered;
    // true (`environment display: before`) on the axiom and after each step, before it is
    // shown. The view file's reader sets it before the program is handed to the parser.
    bool afterStep = false;
    // A fresh run, for a derivation from its axiom.
    virtual std::unique_ptr<ProgramRun> start() const = 0;
    // The turtle's state at one ?E as this program receives it (through the .e formats).
    void receive(const float position[3], const float heading[3], const float left[3], const float up[3],
                 ProgramQuery& q) const;
};

// A program Sprout does not provide, or one that could not start: it answers nothing, and the
// ?E modules keep their values (cpfg goes on without the environment then, too).
class SilentProgram : public EnvironmentProgram {
public:
    std::unique_ptr<ProgramRun> start() const override;
};

// Printf of up to three numbers with a .e file's format: its conversions must be %e %f %g (any
// flags, width and precision) or %%; false with `error` otherwise (the format is the user's).
bool formatTurtleValues(const std::string& format, const float* values, int n, std::string& out, std::string* error);

// The %g text of a float read back as cpfg's comm library does (atof): what crosses the pipe.
float throughText(double value);

}  // namespace sprout
