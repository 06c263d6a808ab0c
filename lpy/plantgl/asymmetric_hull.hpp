#pragma once
// PlantGL's AsymmetricHull (a tree crown) as PlantGL's discretizer makes it, for `@g` shapes
// of L-Py models (lpy/plantgl/meshes.cpp reads the hull's fields and hands them here).
#include <array>
#include <cstdint>
#include <vector>

namespace sprout {

struct AsymmetricHull {
    // Radii and heights of the four quadrant points: negX, posX, negY, posY.
    double negXRadius = 0.5, posXRadius = 0.5, negYRadius = 0.5, posYRadius = 0.5;
    double negXHeight = 0, posXHeight = 0, negYHeight = 0, posYHeight = 0;
    std::array<double, 3> bottom{0, 0, -0.5}, top{0, 0, 0.5};
    double bottomShape = 2, topShape = 2;
    int slices = 4, stacks = 4;
};

struct HullMesh {
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

// Around the z axis, 4 * slices meridians through the points at the four radii (an ellipse in
// each quadrant: x from the x radius on its side, y from the y radius, the height from the two
// quadrant heights as cos^2 and sin^2); each meridian goes from the bottom to its point and on
// to the top in `stacks` steps, evenly in distance from the axis through the bottom (or top)
// point, its height following that distance's power bottomShape (topShape). Then the bottom
// and the top points. Slices and stacks are taken from 1 to 64, the shapes from 1e-6.
HullMesh meshOf(const AsymmetricHull& hull);

}  // namespace sprout
