#pragma once
// Open L-systems and cpfg's query modules, answered between derivation steps (queries.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/environment/cpfg_programs/program.hpp"
#include "core/language/grammar.hpp"

namespace sprout {

// cpfg query modules: interprets `s` with the turtle and writes the frame at each ?P ?H ?U ?L
// into its parameters (position, heading, up, left; as many as the module has).
// ?E modules are answered by the grammar's environment; false with `error` when it cannot
// (a light grid that would be too big). A cpfg environment program (`-e`) answers in `run`, the
// derivation's run of it (null: a fresh run, which remembers nothing of the steps before); with
// `askProgram` false its ?E are left as they are (cpfg asks it as the next step begins, so the
// string of a step shows the ?E unanswered: Derivation does so).
bool answerQueries(const Grammar& grammar, ModuleString& s, int step, std::uint64_t seed, std::string* error = nullptr,
                   ProgramRun* run = nullptr, bool askProgram = true);

// One string whose query modules are answered together with others (a forest sharing one
// environment): its grammar, step and seed, and where the plant stands: its own frame turned
// by `yaw` degrees about +Y and moved to `at`. ?P ?H ?U ?L answer in the plant's own frame;
// ?E asks the shared environment in the world, which sees every plant, and its directions
// come back in the plant's frame.
struct QueryTarget {
    const Grammar* grammar = nullptr;
    ModuleString* string = nullptr;
    int step = 0;
    std::uint64_t seed = 1;
    double yaw = 0;
    glm::dvec3 at{0.0};
};
// `envSeed` seeds the environment's own randomness (attraction points).
bool answerQueriesTogether(const Environment& env, std::uint64_t envSeed, std::vector<QueryTarget>& targets,
                           std::string* error = nullptr, ProgramRun* run = nullptr, bool askProgram = true);

}  // namespace sprout
