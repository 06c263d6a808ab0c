#pragma once
// The environment as a grammar declares it (open L-systems): its shapes and numbers, read from
// `environment:` lines. What it answers the plant is core/environment/environment.hpp.
//
// Open L-systems (Mech and Prusinkiewicz 1996; cpfg's communication modules): after each
// derivation step the string is interpreted, each ?E module is sent with the turtle's frame to
// the environment, and the environment's answer replaces its parameters before the next step.
// Sprout's built-in environments, declared in the grammar with `environment:` lines:
//
//   environment: sphere CX CY CZ R          a region to grow in (topiary): ?E(inside, distance)
//   environment: box X0 Y0 Z0 X1 Y1 Z1      the same for a box
//   environment: ellipsoid CX CY CZ RX RY RZ
//   environment: cylinder CX CY CZ R H      upright, its base at CY
//   environment: mesh FILE.obj              a closed triangle mesh beside the grammar
//       ?E(inside, distance): inside is 1 when the turtle is inside the region (any of the
//       shapes), else 0; distance is its distance to the region's surface (>= 0).
//
//   environment: obstacle sphere|box ...    things to grow around, and
//   environment: ground Y                   the ground plane
//       ?E(length, hit, fx, fy, fz): length (the plant's own value, kept) is how far ahead
//       to look; hit is 1 when the segment from the turtle along its heading that long would
//       enter an obstacle or go below the ground, else 0; (fx, fy, fz) is a free direction:
//       the heading when nothing is hit, else the heading slid along the surface it hits (head-on:
//       n x (1,0,0), or n x (0,0,1) when the normal n is along x).
//
//   environment: light VOXEL [SHADOW] [sun AZIMUTH ELEVATION]
//       light from the sky, shaded by the plant itself
//       ?E(light): the light at the turtle, 1 in the open; each leaf (and, a quarter as much,
//       each stem segment) grown so far casts shadow into a voxel grid of VOXEL-sized cells,
//       SHADOW (0.5 by default) in the cell below it, halving with each cell further down and
//       spreading one cell wider each cell down (shadow propagation, Palubicki et al. 2009);
//       light = max(0, 1 - shadow). With `sun`, the light comes from that direction (degrees:
//       azimuth about +Y from +Z, elevation above the horizon, 90 = overhead, the default) and
//       the shadow is cast away from it.
//
//   environment: attraction N sphere|box|ellipsoid|cylinder ... [influence R] [kill K]
//       space colonisation (Runions, Lane and Prusinkiewicz 2007): N points scattered (seeded)
//       in the shape; a point within K (default 1) of the plant is used up; every other point
//       pulls the one bud nearest to it, if that bud is within R (default 4).
//       ?E(x, y, z, count): the mean direction to the points pulling this bud (unit, or 0 0 0)
//       and how many they are.
//
// A cpfg environment program (`cpfg -e FILE.e`: honda81, ecosystem, clover, a VLab object's
// obcheck) is not declared by a line: the object's .e file is read by readEnviroFile
// (core/environment/cpfg_programs/enviro_file.hpp) and handed to the parser
// (ParseOptions::environmentProgram); it answers the ?E modules as that program does.
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

namespace sprout {

// The tokens of an `environment:` line's value, as [begin, end) byte spans: split at blanks and
// commas, a parenthesised expression kept whole. The parser and the viewer's sliders read the
// line through this one split.
std::vector<std::pair<std::size_t, std::size_t>> environmentTokens(std::string_view value);
// The words of those lines: obstacle, ground, sphere, box, ellipsoid, cylinder, light,
// attraction, influence, kill, mesh, sun (any other name is a define's, in an expression).
bool isEnvironmentKeyword(std::string_view word);

// A closed triangle mesh (an OBJ file's faces, fanned into triangles).
struct TriMesh {
    std::vector<glm::dvec3> vertices;
    std::vector<std::uint32_t> triangles;  // three indices each
    // Parses OBJ text (`v` and `f` lines); false with `error` when it has no faces, an index out
    // of range, or is not closed (an edge that does not belong to exactly two faces).
    bool parse(std::string_view obj, std::string& error);
};

struct EnvShape {
    enum class Kind { Sphere, Box, Ellipsoid, Cylinder, Mesh } kind = Kind::Sphere;
    std::shared_ptr<const TriMesh> mesh;  // Kind::Mesh
    glm::dvec3 a{0.0}, b{0.0};  // sphere: centre, (r, -, -); box: min, max; ellipsoid: centre, radii;
                                // cylinder: base centre, (r, h, -)
    bool contains(const glm::dvec3& p) const;
    double distanceToSurface(const glm::dvec3& p) const;  // >= 0, inside or out
    glm::dvec3 normal(const glm::dvec3& p) const;          // outward, at the surface nearest p
    void box(glm::dvec3& lo, glm::dvec3& hi) const;        // its axis-aligned bounding box
};

// A cpfg environment program, as read from a .e file (core/environment/cpfg_programs/).
class EnvironmentProgram;

struct Environment {
    // A cpfg environment program: when set, it answers every ?E (the shapes below are unused).
    std::shared_ptr<const EnvironmentProgram> program;
    std::vector<EnvShape> region;     // topiary: the union of these
    std::vector<EnvShape> obstacles;  // to grow around
    std::optional<double> ground;     // the ground plane's height
    double lightVoxel = 0;            // > 0: a light environment with voxels this size
    double lightShadow = 0.5;
    double sunAzimuth = 0, sunElevation = 90;  // degrees; where the light comes from
    glm::dvec3 sunDirection() const;           // unit, towards the sun
    // Space colonisation: the points' shape, their number, the radii of influence and kill.
    std::optional<EnvShape> attractionShape;
    int attractionPoints = 0;
    double influence = 4, kill = 1;
    bool isAttraction() const { return attractionShape.has_value(); }
    bool isProgram() const { return program != nullptr; }
    bool empty() const { return !program && region.empty() && obstacles.empty() && !ground && lightVoxel <= 0 && !attractionShape; }
    bool isRegion() const { return !region.empty(); }
    bool isLight() const { return lightVoxel > 0; }

    // The environment's numbers (centres, sizes, distances, the sun's angles) are at most
    // kMaxNumber either way, and its distances (kill, influence, the light's voxel) at least
    // kMinDistance: its points and cells then lie within 1e15 cells of the origin, exact in a
    // double and in a 64-bit cell index. The plant itself may reach any distance (cellKey).
    static constexpr double kMaxNumber = 1e9, kMinDistance = 1e-6;
    // Cells of the light grid are capped so that no plant can exhaust memory with it (buildLight).
    static constexpr std::uint64_t kMaxLightCells = 32'000'000;  // 128 MB of shadow

    // Parses the value of one `environment:` line into this environment; false with `error`.
    bool declare(const std::vector<std::string>& words, const std::vector<double>& numbers, std::string& error);
    // `environment: mesh FILE.obj`: the mesh read from the file (the caller reads it).
    bool declareMesh(std::shared_ptr<const TriMesh> mesh, std::string& error);
};

}  // namespace sprout
