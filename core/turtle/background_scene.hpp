#pragma once
// cpfg's background scene drawn (VLab's cpfg/background.c, DrawPrimitives), the scene
// core/language/vlab/background_scene.hpp reads: triangles appended to a Geometry's polygon
// mesh after the plant's, as cpfg draws them after the plant.
//
//   The matrix: IRIS GL's, each command applied to what follows it (translate, rotate about
//   an axis by degrees, right-handed, scale, multmatrix written row by row with the move in
//   its last row), pushed and popped.
//   Shapes: a polygon and a polygonuv are fans from their first point; a rectangle, a mesh's
//   quads and a prism's faces two triangles each. A flat shape's normal is cpfg's, from its
//   first three points (a b c: (a - b) x (c - b)), the front cpfg lights; a sphere's, a
//   cylinder's and a cone's point outwards. Every triangle winds counter-clockwise about its
//   normal, as exports expect. A cylinder and a cone run along the matrix's y axis from its
//   origin, closed by discs; a sphere's poles are on its z axis; each is cut into the view
//   file's `contour sides:` (3 to 128; a sphere into sides / 2 + 1 bands), as cpfg's are.
//   Colour: the scene starts with colour index 0 of the reference set (its material, or its
//   colour map entry); `material` changes that material (its diffuse colour plus its
//   emission, as the plant's materials; a colour map takes the diffuse colour), and a
//   rectangle's fifth number scales the emission of that rectangle alone. A translucent
//   material keeps its alpha (0xRRGGBBAA).
//
// A shape whose points are not finite numbers (a matrix that overflows) is left out, and at
// most kMaxBackgroundTriangles are drawn (the shapes past them are left out).
#include <cstddef>

#include "core/language/vlab/background_scene.hpp"
#include "core/turtle/geometry.hpp"

namespace sprout {

constexpr std::size_t kMaxBackgroundTriangles = 1'000'000;

// Appends the scene's triangles to `out.polygons` and records them in `out.backdrop`,
// `backdropFirst` and `backdropCount` (not in `out.bounds`: cpfg frames the plant alone). The
// number of triangles drawn.
std::size_t drawBackgroundScene(const vlab::BackgroundScene& scene, Geometry& out);

}  // namespace sprout
