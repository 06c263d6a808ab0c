// sprout export FILE|PRESET -o OUT.glb|.obj|.ply|.svg [-n N] [--seed S] [--sides K] [--with-environment]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <unistd.h>

#include "app/args.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/load.hpp"
#include "app/plant/growth.hpp"
#include "app/plant/scene.hpp"
#include "core/environment/environment_drawing.hpp"
#include "app/export/export.hpp"
#include "app/plant/presets.hpp"
#include "core/derive/derive.hpp"
#include "core/turtle/turtle.hpp"

namespace sprout::cli {

int runExport(int argc, char** argv) {
    Args args(argc, argv, 1, {"--quiet", "--with-environment", "--no-python"}, {"-o", "-n", "--seed", "--sides", "--max-modules", "--max-memory", "--format"});
    auto n = args.integer("-n", 0, 10000);
    auto seed = args.integer("--seed", 0, INT64_MAX);
    auto sides = args.integer("--sides", 3, 64);
    auto maxModules = args.integer("--max-modules", 1, INT64_MAX);
    auto maxMemory = args.integer("--max-memory", 1, INT64_MAX / (1 << 20));
    std::string problem = args.error();
    if (problem.empty() && (args.positionals().size() != 1 || !args.value("-o")))
        problem = "expects one FILE or PRESET and -o OUT";
    // `-o -` writes to standard output, in the --format given (glb by default).
    std::optional<exporter::Format> format;
    if (problem.empty() && args.value("--format")) {
        if (!(format = exporter::formatFromPath("x." + *args.value("--format"))))
            problem = "unknown --format " + *args.value("--format") + ": use glb, obj, ply or svg";
    } else if (problem.empty() && *args.value("-o") == "-") {
        format = exporter::Format::Glb;
    } else if (problem.empty() && !(format = exporter::formatFromPath(*args.value("-o")))) {
        problem = "cannot tell the format of " + *args.value("-o") + ": use .glb, .obj, .ply or .svg (or --format)";
    }
    if (!problem.empty()) {
        std::cerr << "sprout export: " << problem
                  << "\nusage: sprout export FILE|PRESET -o OUT.glb|OUT.obj|OUT.ply|OUT.svg|- [--format glb|obj|ply|svg] [-n N]"
                     " [--seed S] [--sides K] [--with-environment] [--max-modules M] [--max-memory MB] [--quiet] [--no-python]\n"
                     "       An L-Py model (.lpy) is a Python program: it runs as `python3 FILE` would; --no-python refuses it.\n";
        return 2;
    }
    const std::string source = args.positionals()[0], out = *args.value("-o");
    auto t0 = std::chrono::steady_clock::now();
    Geometry geometry;
    Environment environment;  // what the plant grew in, exported with it when asked
    std::uint64_t usedSeed = 1;
    DeriveLimits limits;
    if (maxModules) limits.maxModules = std::uint64_t(*maxModules);
    if (maxMemory) limits.maxBytes = std::uint64_t(*maxMemory) << 20;
    const FileKind kind = sourceKind(source);  // a picture written by Sprout holds what it shows
    if (kind == FileKind::Ifs) {
        std::cerr << source << ": an iterated function system is a point density, not a model; "
                     "`sprout render` draws it as a picture\n";
        return 1;
    } else if (kind == FileKind::Forest) {
        ForestStats fs;
        std::string text;
        if (!buildForestScene(source, seed ? std::optional<std::uint64_t>(*seed) : std::nullopt, limits, geometry, fs, text, printReport,
                              &environment, &usedSeed))
            return 1;
    } else {
        LoadOptions lo;
        lo.steps = n ? int(*n) : -1;
        lo.python = !args.flag("--no-python");
        if (maxModules) lo.maxModules = limits.maxModules;
        if (maxMemory) lo.maxBytes = limits.maxBytes;
        auto loaded = loadGrammar(source, lo);
        if (!loaded) return 1;
        const Grammar& g = *loaded->grammar;
        const int steps = n && !loaded->ranPython ? int(*n) : g.settings.iterations;
        DeriveOptions dopts;
        if (seed) dopts.seed = std::uint64_t(*seed);
        dopts.limits = limits;
        std::string error;
        if (!growAndDraw(loaded->grammar, steps, dopts, geometry, error, &usedSeed)) {
            std::cerr << loaded->displayName << ": " << error << "\n";
            return 1;
        }
        environment = g.environment;
    }
    if (args.flag("--with-environment") && !environment.empty()) {
        // The environment's shapes as the viewer draws them, as polygons beside the plant.
        Mesh shapes;
        std::string error;
        if (!drawEnvironment(environment, geometry, usedSeed, {}, shapes, &error)) {
            std::cerr << source << ": " << error << "\n";
            return 1;
        }
        const std::uint32_t base = std::uint32_t(geometry.polygons.positions.size());
        for (size_t i = 0; i < shapes.positions.size(); ++i) {
            geometry.polygons.positions.push_back(shapes.positions[i]);
            geometry.polygons.normals.push_back(shapes.normals[i]);
            geometry.polygons.colours.push_back(shapes.colours[i] | 0xffu);  // opaque: not every format has alpha
            geometry.bounds.add(shapes.positions[i]);
        }
        for (std::uint32_t i : shapes.indices) geometry.polygons.indices.push_back(base + i);
    }
    // A progress line on a terminal for big plants.
    const bool tty = isatty(2) && !args.flag("--quiet");
    exporter::ExportOptions o;
    o.sides = sides ? int(*sides) : 0;
    o.generator = "Sprout " SPROUT_VERSION;
    int lastPercent = -1;
    if (tty && geometry.cylinders.size() > 100000)
        o.progress = [&](double f) {
            int p = int(f * 100);
            if (p != lastPercent) std::fprintf(stderr, "\rexporting %s: %3d%%", out.c_str(), lastPercent = p);
        };
    exporter::ExportStats st;
    std::string error;
    bool ok = exporter::exportGeometry(geometry, out, *format, o, st, error);
    if (lastPercent >= 0) std::fprintf(stderr, "\n");
    if (!ok) {
        std::cerr << out << ": " << error << "\n";
        return 1;
    }
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!args.flag("--quiet")) {
        if (*format == exporter::Format::Svg)
            std::fprintf(out == "-" ? stderr : stdout, "%s: %zu segments, %zu filled triangles, %.1f KB in %.2f s\n", out.c_str(), geometry.cylinders.size(),
                        st.triangles, double(st.bytes) / 1024, secs);
        else
            std::fprintf(out == "-" ? stderr : stdout, "%s: %zu segments as %zu tubes, %zu surfaces; %zu triangles, %zu vertices, %zu materials; %.1f MB in %.2f s\n",
                        out.c_str(), geometry.cylinders.size(), st.stems, geometry.surfaces.size(), st.triangles, st.vertices,
                        st.materials, double(st.bytes) / (1 << 20), secs);
    }
    return 0;
}

}  // namespace sprout::cli
