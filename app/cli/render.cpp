// sprout render FILE|PRESET -o out.png [--size WxH] [-n N] [--seed S] [--view front|side|top|iso]
//                                      [--yaw DEG] [--pitch DEG] [--no-shadows] [--no-ground] [--stats]
//                                      [--show-environment] [--light-slice H] [--detail full|viewer]
// Renders through OSMesa: no display and no GLFW, the same shaders as the window.
#include <cstdio>
#include <iostream>

#include "app/args.hpp"
#include "app/cli/commands.hpp"
#include "app/labels.hpp"
#include "app/animation.hpp"
#include "app/cli/load.hpp"
#include "app/plant/presets.hpp"
#include "app/plant/scene.hpp"
#include "app/plant/source.hpp"
#include "core/base/read_file.hpp"
#include "app/snapshot.hpp"
#include "app/plant/text_edit.hpp"
#include "core/language/import/import.hpp"
#include "core/language/file_kind.hpp"
#include "core/scene/forest.hpp"

#include <algorithm>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace sprout::cli {
namespace {

// What a command says about its work goes to standard output, unless the picture itself does
// (`-o -`): then to standard error, so that `sprout render koch -o - | display` gets a PNG.
std::FILE* info(const std::string& out) { return out == "-" ? stderr : stdout; }


bool parseFloat(const std::optional<std::string>& s, std::optional<float>& out) {
    if (!s) return true;
    char* end = nullptr;
    float v = std::strtof(s->c_str(), &end);
    if (end == s->c_str() || *end || !std::isfinite(v)) return false;
    out = v;
    return true;
}

// "X,Y,Z"
bool parsePoint(const std::optional<std::string>& s, std::optional<glm::vec3>& out) {
    if (!s) return true;
    glm::vec3 p;
    const char* at = s->c_str();
    for (int k = 0; k < 3; ++k) {
        char* end = nullptr;
        p[k] = std::strtof(at, &end);
        if (end == at || !std::isfinite(p[k]) || *end != (k < 2 ? ',' : '\0')) return false;
        at = end + 1;
    }
    out = p;
    return true;
}

// An iterated function system: the chaos game into a density image, log tone mapped.
int renderIfs(const std::string& source, const SnapshotOptions& o, const std::string& out, bool stats) {
    std::string text;
    if (auto preset = presetText(source); preset && !std::filesystem::exists(source)) {
        text = std::string(*preset);
    } else {
        auto t = readSourceOrChunk(source, "ifs");
        if (!t) {
            std::cerr << source << ": cannot be opened\n";
            return 1;
        }
        text = std::move(*t);
    }
    IfsPicture picture = drawIfs(text, o.seed, o.width, o.height, int(std::max(1u, std::thread::hardware_concurrency())));
    for (const auto& d : picture.diagnostics) std::cerr << formatDiagnostic(d, source) << "\n";
    if (!picture.parsed) return 1;
    Image img;
    img.width = o.width;
    img.height = o.height;
    img.rgba = std::move(picture.rgba);
    img.text.emplace_back("ifs", text);
    std::string error;
    if (!writePng(out, img, error)) {
        std::cerr << out << ": " << error << "\n";
        return 1;
    }
    if (stats) std::fprintf(info(out), "%s: %s points of the chaos game in %.0f ms\n", out.c_str(), withThousands(picture.points).c_str(), picture.gameMs);
    return 0;
}

}  // namespace


namespace {

int renderForest(const std::string& source, SnapshotOptions o, const std::string& out, bool stats) {
    std::string text, error;
    Snapshot shot;
    ForestStats fs;
    auto t0 = std::chrono::steady_clock::now();
    auto environment = std::make_shared<Environment>();
    std::uint64_t seed = 1;
    if (!buildForestScene(source, o.seed, o.limits, shot.geometry, fs, text, printReport, environment.get(), &seed)) return 1;
    double buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    o.environment = environment;
    if (!renderGeometry(o, shot, error, seed)) {
        std::cerr << source << ": " << error << "\n";
        return 1;
    }
    shot.image.text.emplace_back("forest", text);
    if (!writePng(out, shot.image, error)) {
        std::cerr << out << ": " << error << "\n";
        return 1;
    }
    if (stats)
        std::fprintf(info(out), "%s: %d plants, %d grasses, %s segments; built in %.0f ms, rendered in %.0f ms\n", out.c_str(), fs.plants,
                    fs.grasses, withThousands(fs.segments).c_str(), buildMs, shot.renderMs);
    return 0;
}

}  // namespace

namespace {

// The picture's options read from the command line into `o` (and what to animate); what is
// wrong with them, or nothing.
std::string readPictureOptions(const Args& args, bool hasFramesOrFps, SnapshotOptions& o, std::optional<AnimationKind>& animate) {
    if (auto a = args.value("--animate")) {
        if (*a == "growth") animate = AnimationKind::Growth;
        else if (*a == "turntable") animate = AnimationKind::Turntable;
        else return "--animate expects growth or turntable";
    }
    if (hasFramesOrFps && !animate) return "--frames and --fps go with --animate growth|turntable";
    if (args.value("--size") && !parseSize(*args.value("--size"), o.width, o.height))
        return "--size expects WIDTHxHEIGHT between 16x16 and 8192x8192, e.g. 1280x720";
    if (!parseFloat(args.value("--yaw"), o.yaw) || !parseFloat(args.value("--pitch"), o.pitch))
        return "--yaw and --pitch expect degrees";
    if (!parseFloat(args.value("--distance"), o.distance) || (o.distance && !(*o.distance > 0)))
        return "--distance expects a positive number (from the camera to its target)";
    if (!parsePoint(args.value("--target"), o.target))
        return "--target expects X,Y,Z (the point the camera looks at)";
    if (auto v = args.value("--view")) {
        if (*v == "front") o.view = render::ViewPreset::Front;
        else if (*v == "side") o.view = render::ViewPreset::Side;
        else if (*v == "top") o.view = render::ViewPreset::Top;
        else if (*v == "iso") o.view = render::ViewPreset::Iso;
        else if (*v != "auto") return "--view expects front, side, top, iso or auto";
    }
    std::optional<float> slice;
    if (!parseFloat(args.value("--light-slice"), slice) || (slice && !(*slice >= 0 && *slice <= 1)))
        return "--light-slice expects a height from 0 (the plant's lowest point) to 1 (its top)";
    o.showEnvironment = args.flag("--show-environment") || slice;
    o.environmentView.lightSlice = slice.has_value();
    if (slice) o.environmentView.sliceHeight = *slice;
    if (auto d = args.value("--detail")) {
        if (*d == "viewer") o.viewerDetail = true;
        else if (*d != "full") return "--detail expects full (the default) or viewer (a big plant as the viewer window draws it)";
    }
    return {};
}

// The view a picture was rendered with comes back with it, unless one is given now: the view
// the picture will carry (its --view, --yaw... as given), and `o` set to it.
std::string viewToKeep(const Args& args, const std::string& source, SnapshotOptions& o) {
    std::string view;
    for (const char* k : {"--view", "--yaw", "--pitch", "--distance", "--target"})
        if (auto v = args.value(k)) view += std::string(view.empty() ? "" : " ") + k + " " + *v;
    if (view.empty() && source.size() > 4 && source.substr(source.size() - 4) == ".png") {
        std::string png = readFile(source).value_or(""), ignored;
        if (auto v = pngTextChunk(png, "sprout-view", ignored)) {
            std::istringstream words(*v);
            std::string k, value;
            while (words >> k >> value) {
                if (k == "--view") o.view = value == "front" ? render::ViewPreset::Front : value == "side" ? render::ViewPreset::Side
                                          : value == "top"   ? render::ViewPreset::Top   : value == "iso" ? render::ViewPreset::Iso
                                                             : o.view;
                std::optional<float> f;
                if ((k == "--yaw" || k == "--pitch") && parseFloat(value, f) && f) (k == "--yaw" ? o.yaw : o.pitch) = f;
                if (k == "--distance" && parseFloat(value, f) && f && *f > 0) o.distance = f;
                if (k == "--target") parsePoint(value, o.target);
            }
            view = *v;
        }
    }
    return view;
}

// A growth or turntable video (or numbered frames) of the loaded plant.
int renderVideo(const LoadedGrammar& loaded, AnimationKind kind, const SnapshotOptions& o, const std::string& recipe,
                std::optional<std::int64_t> frames, std::optional<std::int64_t> fps, const std::string& out) {
    AnimationOptions ao;
    ao.kind = kind;
    if (frames) ao.frames = int(*frames);
    if (fps) ao.fps = int(*fps);
    ao.recipe = recipe;
    ao.steps = loaded.steps;
    // A VLab object's animation file says which steps growth shows, unless --frames does.
    if (const auto& p = loaded.grammar->settings.picture; p && !frames && !o.iterations) ao.shownSteps = p->frames;
    const bool tty = isatty(2);
    if (tty)
        ao.progress = [&](int k, int total) {
            std::fprintf(stderr, "\rrendering frame %d of %d", k, total);
            if (k == total) std::fprintf(stderr, "\n");
        };
    AnimationResult ar;
    std::string error;
    auto t0 = std::chrono::steady_clock::now();
    if (!renderAnimation(loaded.grammar, o, ao, out, ar, error)) {
        std::cerr << out << ": " << error << "\n";
        return 1;
    }
    if (!ar.note.empty()) std::cerr << out << ": " << ar.note << "\n";
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::fprintf(info(out), "%s: %d frames%s in %.1f s\n", ar.video ? out.c_str() : ar.firstFrame.c_str(), ar.frames,
                ar.video ? "" : " (numbered PNG files)", secs);
    return 0;
}

// The sky (and ground, unless --no-ground) left out: each pixel the plant does not change from
// the empty scene seen by the same camera is transparent (icons, overlays).
bool makeSkyTransparent(Snapshot& shot, const SnapshotOptions& o, std::string& error) {
    const render::Camera c = snapshotCamera(shot.geometry, o);
    SnapshotOptions e = o;
    e.yaw = c.yaw;
    e.pitch = c.pitch;
    e.distance = c.distance;
    e.target = c.target;
    e.showEnvironment = false;
    Snapshot empty;
    if (!renderGeometry(e, empty, error)) return false;
    auto& px = shot.image.rgba;
    const auto& bg = empty.image.rgba;
    for (std::size_t i = 0; i + 3 < px.size() && i + 3 < bg.size(); i += 4) {
        const int d = std::max({std::abs(int(px[i]) - int(bg[i])), std::abs(int(px[i + 1]) - int(bg[i + 1])),
                                std::abs(int(px[i + 2]) - int(bg[i + 2]))});
        px[i + 3] = std::uint8_t(d <= 2 ? 0 : d >= 24 ? 255 : d * 255 / 24);  // soft edges where the plant meets the sky
    }
    return true;
}

void printPictureStats(const Snapshot& shot, const std::string& out) {
    std::fprintf(info(out), "%s: %zu segments (%s), %zu surfaces, %zu triangles; derive %.1f ms, interpret %.1f ms, "
                "render %.1f ms\n",
                out.c_str(), shot.stats.cylinders,
                shot.stats.curve ? "2D curve"
                                 : ("fine " + std::to_string(shot.stats.levels[0]) + ", coarse " +
                                    std::to_string(shot.stats.levels[1]) + ", prisms " + std::to_string(shot.stats.levels[2]) +
                                    ", lines " + std::to_string(shot.stats.levels[3]))
                                       .c_str(),
                shot.stats.surfaces, shot.stats.triangles, shot.deriveMs, shot.interpretMs, shot.renderMs);
}

}  // namespace

int runRender(int argc, char** argv) {
    Args args(argc, argv, 1, {"--no-shadows", "--no-ground", "--transparent", "--stats", "--show-environment", "--no-python"},
              {"-o", "--size", "-n", "--seed", "--view", "--yaw", "--pitch", "--distance", "--target", "--max-modules", "--max-memory", "--animate",
               "--frames", "--fps", "--light-slice", "--detail"});
    SnapshotOptions o;
    auto n = args.integer("-n", 0, 10000);
    auto seed = args.integer("--seed", 0, INT64_MAX);
    auto maxModules = args.integer("--max-modules", 1, INT64_MAX);
    auto maxMemory = args.integer("--max-memory", 1, INT64_MAX / (1 << 20));
    auto frames = args.integer("--frames", 1, 100000);
    auto fps = args.integer("--fps", 1, 240);
    std::optional<AnimationKind> animate;
    std::string problem = args.error();
    if (problem.empty()) problem = readPictureOptions(args, bool(frames || fps), o, animate);
    if (problem.empty() && (args.positionals().size() != 1 || !args.value("-o")))
        problem = "expects one FILE or PRESET and -o OUT.png";
    if (!problem.empty()) {
        std::cerr << "sprout render: " << problem
                  << "\nusage: sprout render FILE|PRESET -o out.png [--size 1280x720] [-n N] [--seed S]"
                     " [--view front|side|top|iso] [--yaw DEG --pitch DEG] [--distance D] [--target X,Y,Z]"
                     " [--no-shadows] [--no-ground] [--transparent] [--show-environment] [--light-slice H] [--detail full|viewer]"
                     " [--max-modules M] [--max-memory MB] [--no-python]\n"
                     "       An L-Py model (.lpy) is a Python program: it runs as `python3 FILE` would; --no-python refuses it.\n"
                     "       sprout render FILE|PRESET --animate growth|turntable -o out.mp4|frames.png [--frames N] [--fps F] ...\n";
        return 2;
    }
    const std::string source = args.positionals()[0];
    const std::string view = viewToKeep(args, source, o);
    // A PNG of an IFS or a forest scene is rendered as what it holds.
    const FileKind kind = sourceKind(source);
    if (maxModules) o.limits.maxModules = std::uint64_t(*maxModules);
    if (maxMemory) o.limits.maxBytes = std::uint64_t(*maxMemory) << 20;
    if (kind == FileKind::Ifs) return renderIfs(source, o, *args.value("-o"), args.flag("--stats"));
    if (kind == FileKind::Forest) return renderForest(source, o, *args.value("-o"), args.flag("--stats"));
    LoadOptions lo;
    lo.steps = n ? int(*n) : -1;
    lo.python = !args.flag("--no-python");
    lo.keepSteps = animate == AnimationKind::Growth;
    if (maxModules) lo.maxModules = std::uint64_t(*maxModules);
    if (maxMemory) lo.maxBytes = std::uint64_t(*maxMemory) << 20;
    // The picture's GL side is made ready on another thread while the model is read and run.
    o.render.shadows = !args.flag("--no-shadows");
    o.render.ground = !args.flag("--no-ground");
    const PreparedSnapshotWait waitForIt;
    if (!animate) prepareSnapshot(o.width, o.height, o.render);
    auto loaded = loadGrammar(source, lo);
    if (!loaded) return 1;
    if (n && !loaded->ranPython) o.iterations = int(*n);
    // A VLab object's view: its camera, light, background and window size (app/snapshot.hpp).
    if (const auto& p = loaded->grammar->settings.picture) usePictureView(*p, o, args.value("--size").has_value());
    if (seed) o.seed = std::uint64_t(*seed);

    // The grammar travels inside the PNG, so the picture can be opened again: with -n and
    // --seed written into it, it gives this very plant back.
    std::string recipe = loaded->text;
    if (n && !loaded->ranPython) recipe = setDirective(recipe, directiveValue(recipe, "iterations") ? "iterations" : "n", std::to_string(*n));
    if (seed) recipe = setDirective(recipe, "seed", std::to_string(*seed));
    if (animate) return renderVideo(*loaded, *animate, o, recipe, frames, fps, *args.value("-o"));
    Snapshot shot;
    std::string error;
    if (!renderSnapshot(loaded->grammar, o, shot, error)) {
        std::cerr << loaded->displayName << ": " << error << "\n";
        return 1;
    }
    paintLabels(shot.image, shot.geometry, snapshotCamera(shot.geometry, o));
    if (args.flag("--transparent") && !makeSkyTransparent(shot, o, error)) {
        std::cerr << loaded->displayName << ": " << error << "\n";
        return 1;
    }
    shot.image.text.emplace_back("lsys", recipe);
    if (!view.empty()) shot.image.text.emplace_back("sprout-view", view);
    shot.image.text.emplace_back("Software", "Sprout " SPROUT_VERSION);
    const std::string out = *args.value("-o");
    if (!writePng(out, shot.image, error)) {
        std::cerr << out << ": " << error << "\n";
        return 1;
    }
    if (args.flag("--stats")) printPictureStats(shot, out);
    return 0;
}

}  // namespace sprout::cli
