#pragma once
// Sources that are scenes, not one grammar (app/plant/README.md): a forest scene grown into one
// geometry, and an iterated function system drawn by the chaos game. The one way each grows, for
// the command line and the viewer's worker.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/plant/open.hpp"
#include "core/derive/derive.hpp"
#include "core/language/diagnostic.hpp"
#include "core/scene/forest.hpp"

namespace sprout {

// A forest scene's text grown into one geometry (core/scene's buildForest): its species read by
// `species`, an environment's files beside `path` (the scene's file; empty: none). The one way
// a scene grows, for the command line and the viewer's worker.
struct GrownScene {
    std::vector<Diagnostic> diagnostics;  // the scene's text's
    bool parsed = false;                  // the text is a scene (else its diagnostics say why)
    bool built = false;                   // and it grew (else `error` says why)
    std::string error;
    std::uint64_t seed = 1;               // the seed it grew with
    Environment environment;              // the environment its plants share (empty: none)
    ForestStats stats;
};
GrownScene growScene(const std::string& text, const std::string& path, std::optional<std::uint64_t> seed,
                     const GrammarSource& species, const DeriveLimits& limits, Geometry& geometry,
                     std::vector<ForestPlant>* plants = nullptr);

// A forest scene's species `name`: the file of that name in the first of `folders` where one
// is (its text), else the preset of that name; nullopt when there is neither.
std::optional<std::string> speciesText(const std::string& name, const std::vector<std::filesystem::path>& folders);

// A forest scene (.forest file or scene preset) built into one geometry, its species presets or
// files beside the scene's file; `text` is the scene as written. Reports diagnostics; false
// when it cannot be built.
// `environment`, when given, receives the scene's shared environment (empty when it has none).
bool buildForestScene(const std::string& source, std::optional<std::uint64_t> seed, const DeriveLimits& limits,
                      Geometry& geometry, ForestStats& stats, std::string& text, const Report& report,
                      Environment* environment = nullptr, std::uint64_t* usedSeed = nullptr);

// An iterated function system's text drawn by the chaos game (`threads` streams, each seeded)
// into a density of width x height, tone mapped onto Sprout's paper colour (0xRRGGBBAA).
struct IfsPicture {
    std::vector<Diagnostic> diagnostics;  // the text's
    bool parsed = false;                  // the text is a system (else its diagnostics say why)
    bool drawn = false;                   // and the game was played (false: cancelled)
    std::uint64_t seed = 1, points = 0;   // the seed it played with, the points it played
    double gameMs = 0;                    // the chaos game's time, tone mapping aside
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};
IfsPicture drawIfs(const std::string& text, std::optional<std::uint64_t> seed, int width, int height, int threads,
                   const std::atomic<bool>* cancel = nullptr);

}  // namespace sprout
