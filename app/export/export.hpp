#pragma once
// Geometry -> files other programs open: glTF 2.0 binary, OBJ + MTL, binary PLY, SVG.
// Meshes are streamed: stems are baked to triangles a few thousand at a time and written
// straight out, so a plant of millions of segments never exists twice in memory.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "core/turtle/geometry.hpp"

namespace sprout::exporter {

enum class Format { Glb, Obj, Ply, Svg };

// From the file extension (case-insensitive); nullopt for anything else.
std::optional<Format> formatFromPath(const std::string& path);

struct ExportOptions {
    // Sides of a stem's tube; 0 chooses per stem from its thickness relative to the plant
    // (10 for thick stems, 7 for medium, 5 for thin twigs).
    int sides = 0;
    std::string generator = "Sprout";
    // Called now and then with the fraction written so far (0..1).
    std::function<void(double)> progress;
};

struct ExportStats {
    std::size_t vertices = 0, triangles = 0, primitives = 0, materials = 0;
    std::size_t stems = 0;  // tubes after merging straight runs
    std::uint64_t bytes = 0;
};

// False with a message when the file cannot be written.
bool exportGeometry(const Geometry& geometry, const std::string& path, Format format, const ExportOptions& options,
                    ExportStats& stats, std::string& error);

}  // namespace sprout::exporter
