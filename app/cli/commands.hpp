#pragma once
// The subcommands of `sprout`. Each returns the process exit code.

namespace sprout::cli {

int runExpand(int argc, char** argv);  // argv[0] is "expand"
int runRender(int argc, char** argv);  // argv[0] is "render"
int printUsage(bool toStderr);

}  // namespace sprout::cli
