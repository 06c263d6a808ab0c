#pragma once
// Forest scenes (seed document 003, section 4.5): species with shares planted on a jittered
// grid, each plant its own stochastic specimen, with an optional layer of grass.
//
//   scene: forest
//   grid: 10 10            # columns, rows
//   spacing: 30            # distance between grid points
//   seed: 7
//   species: tree_4_3 0.5  # a preset name or a file, and its share
//   species: bushy_tree_4_4 0.4
//   species: broken_tree_4_4 0.1
//   grass: grass_4_4 4     # grass specimens per cell (optional)
//   environment: light 2   # one environment shared by every plant (optional, as in a grammar)
//
// With an `environment:`, the plants whose grammars ask ?E grow in lockstep, and after each
// step the one environment answers them all where they stand: they shade each other (light),
// compete for the same attraction points, grow around the same obstacles. It replaces any
// environment of their own. Plants that ask nothing grow on their own as before.
//
// Positions move by up to 30% of the cell, whole rows and columns by up to 20%; each plant
// turns about the vertical by N(180, 60) degrees (kept positive), as in the document.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/derive/derive.hpp"
#include "core/language/file_kind.hpp"  // isForestScene
#include "core/turtle/geometry.hpp"

namespace sprout {

struct Forest {
    int columns = 10, rows = 10;
    double spacing = 30;
    std::uint64_t seed = 1;
    struct Species {
        std::string name;
        double share = 1;
        int line = 0;
    };
    std::vector<Species> species;
    std::string grass;
    int grassPerCell = 0;
    Environment environment;  // shared by every plant that asks ?E; empty: none
};


struct ForestParseResult {
    std::optional<Forest> forest;
    std::vector<Diagnostic> diagnostics;
};
// `include` reads the files an environment names (a mesh) beside the scene; without it they are an error.
ForestParseResult parseForest(std::string_view text, const IncludeReader& include = {});

// Looks up a species' grammar text by name (a preset or a file); nullopt when unknown.
using GrammarSource = std::function<std::optional<std::string>(const std::string& name)>;

struct ForestStats {
    int plants = 0, grasses = 0;
    std::uint64_t segments = 0;
    int sharing = 0;  // plants grown in lockstep with the shared environment
};

// One plant of a built forest and where its instances are in the forest's geometry (picking:
// which plant, which species).
struct ForestPlant {
    std::string species;
    glm::vec3 at{0.0f};
    float yaw = 0;
    bool grass = false;
    std::uint32_t firstSegment = 0, segments = 0, firstSurface = 0, surfaces = 0;
};

// Grows every plant and gathers them into one Geometry. False with a message on failure.
// `plants`, when given, receives each plant's place in it.
bool buildForest(const Forest& forest, const GrammarSource& source, Geometry& out, ForestStats& stats,
                 std::string& error, const DeriveLimits& limits = {}, std::vector<ForestPlant>* plants = nullptr);

}  // namespace sprout
