#pragma once
// The viewer's public face: what main.cpp opens when no subcommand is given.

namespace sprout::viewer {

// The GLFW window on a FILE or PRESET (argv[0] is the program); the exit code.
int runViewer(int argc, char** argv);

}  // namespace sprout::viewer
