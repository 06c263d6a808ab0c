#pragma once
#include <string>
// The subcommands of `sprout`. Each returns the process exit code.

namespace sprout::cli {

int runExpand(int argc, char** argv);  // argv[0] is "expand"
int runRender(int argc, char** argv);  // argv[0] is "render"
int runExport(int argc, char** argv);  // argv[0] is "export"
int printUsage(bool toStderr);

}  // namespace sprout::cli
