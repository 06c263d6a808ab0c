// sprout: with no subcommand, the viewer; `sprout expand | render | export ...` need no display.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <iostream>
#include <new>

#include "app/cli/commands.hpp"
#include "app/plant/presets.hpp"
#include "app/viewer/window/viewer.hpp"

namespace sprout::cli {

int printUsage(bool toStderr) {
    std::FILE* out = toStderr ? stderr : stdout;
    std::fprintf(out,
                 "Sprout %s, a workbench for L-systems\n\n"
                 "usage:\n"
                 "  sprout [FILE|PRESET] [--size WxH] [--screenshot OUT.png] [--script FILE]\n"
                 "                                  open the viewer (without a display: writes sprout.png)\n"
                 "  sprout expand FILE|PRESET [-n N] [--seed S] [--stats] [--max-modules M] [--max-memory MB]\n"
                 "                                  print the derived string of step N\n"
                 "  sprout render FILE|PRESET -o out.png [--size WxH] [-n N] [--seed S] [--view front|side|top|iso]\n"
                 "                [--yaw DEG] [--pitch DEG] [--no-shadows] [--no-ground] [--transparent] [--stats] [--detail full|viewer]\n"
                 "                                  render a picture with no display (OSMesa)\n"
                 "  sprout render FILE|PRESET --animate growth|turntable -o out.mp4 [--frames N] [--fps F]\n"
                 "                                  a growth or turntable video (ffmpeg), or PNG frames\n"
                 "  sprout export FILE|PRESET -o OUT.glb|.obj|.ply|.svg [-n N] [--seed S] [--sides K]\n"
                 "                                  write a model (glTF binary, OBJ + MTL, PLY) or an SVG drawing\n"
                 "  sprout presets                  list the built-in presets\n"
                 "  sprout --help | --version\n",
                 SPROUT_VERSION);
    return toStderr ? 2 : 0;
}

}  // namespace sprout::cli

static int run(int argc, char** argv);

int main(int argc, char** argv) {
    // Limits raised past what the machine has end in a message, not an abort.
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "sprout: out of memory; lower n or the limits (--max-modules, --max-memory)\n");
        return 1;
    }
}

static int run(int argc, char** argv) {
    using namespace sprout;
    if (argc >= 2) {
        const char* cmd = argv[1];
        if (!std::strcmp(cmd, "expand")) return cli::runExpand(argc - 1, argv + 1);
        if (!std::strcmp(cmd, "render")) return cli::runRender(argc - 1, argv + 1);
        if (!std::strcmp(cmd, "export")) return cli::runExport(argc - 1, argv + 1);
        if (!std::strcmp(cmd, "presets")) {
            for (const auto& name : presetNames()) std::printf("%s\n", name.c_str());
            return 0;
        }
        if (!std::strcmp(cmd, "--help") || !std::strcmp(cmd, "-h")) return cli::printUsage(false);
        if (!std::strcmp(cmd, "--version")) {
            std::printf("sprout %s\n", SPROUT_VERSION);
            return 0;
        }
    }
    // No subcommand: the viewer. Without a display, say so and leave a picture instead.
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) {
        std::string source(kDefaultPreset);
        for (int i = 1; i < argc; ++i)
            if (argv[i][0] != '-') {
                source = argv[i];
                break;
            }
        std::string out = "sprout.png";
        std::fprintf(stderr, "sprout: no display found; writing a headless render of %s to %s instead\n",
                     source.c_str(), out.c_str());
        std::string o = "-o";
        char* renderArgv[] = {const_cast<char*>("render"), source.data(), o.data(), out.data()};
        return cli::runRender(4, renderArgv);
    }
    return viewer::runViewer(argc, argv);
}
