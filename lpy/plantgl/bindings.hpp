#pragma once
// The C++ under Sprout's Python PlantGL (lpy/README.md): the classes and functions its Python
// (plantgl_*.py) calls, and what the drawing asks of a curve or a shape without calling Python.
#include <pybind11/pybind11.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "lpy/plantgl/curves.hpp"

namespace sprout::lpy {

// The C++ evaluator of one of Sprout's NURBS curves (NurbsCurve2D, NurbsCurve, BezierCurve2D,
// whose methods it evaluates as they would), and its stride; null for any other object (or
// a subclass that replaces how it is evaluated). Holds the GIL; clears any Python error.
std::shared_ptr<const curves::Nurbs> nativeNurbs(PyObject* curve, int& stride);

// A PlantGL shape given to @g made into its points in the shape's frame, and triangles and
// segments indexing them (lpy/plantgl/meshes.cpp): Nothing where nothing is drawn (no shape,
// text, a value the shape cannot be made of). Holds the GIL; clears any Python error.
struct ShapeMesh {
    enum Kind { Nothing, Mesh } kind = Nothing;
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<long, 3>> triangles;
    std::vector<std::array<long, 2>> segments;
    // Each point's colour (0xRRGGBBAA) where a Shape's Material gave it, as PglTurtle::pglShape
    // draws a shape in its own appearance; 0 (or none at all): the turtle's colour.
    std::vector<std::uint32_t> colours;
    // Each point's texture coordinates where the shape has them (patches, solids, meshes with
    // a texCoordList); else none.
    std::vector<std::array<float, 2>> uvs;
    // Where a point is a copy of another (a seam, a cap's ring, a face's corner with texture
    // coordinates of its own), that point: they share one normal, as if not copied. Empty:
    // none is.
    std::vector<long> sameNormal;
    // The image of a Shape with a texture appearance around them (the first such), as the
    // model names it; "": the turtle's material's.
    std::string texture;
};
ShapeMesh shapeMesh(PyObject* shape);
// `mesh` without its copied points (ShapeMesh::sameNormal), the triangles on the points they
// copy: the shape's geometry alone, as it was meshed before texture coordinates were given.
ShapeMesh welded(const ShapeMesh& mesh);
// A Shape's colour as PglTurtle::pglShape draws it: its Material's diffuseColor() and, as
// alpha, 1 - transparency (0xRRGGBBAA); 0 for another appearance (a texture) or none
// (appearance.cpp).
std::uint32_t shapeColour(PyObject* shape);
// A Shape's texture appearance's image file (a Texture2D's ImageTexture, or an ImageTexture),
// as the model names it; "" for another appearance.
std::string shapeTexture(PyObject* shape);
// An AsymmetricHull given alone to @g, its fields read leniently (any value not a number: the
// field's default), as the drawing has always read it (lpy/draw/shapes.cpp).
ShapeMesh hullMesh(PyObject* hull);

// The (n + 1)^2 points at (i / n, j / n), i outer, of a NurbsPatch of `rows` (control points,
// read as plantgl_curves.py's NurbsPatch reads them), the uniform knots (bind_curves.cpp).
// Throws where the Python patch would raise.
std::vector<curves::Point> patchGrid(PyObject* rows, int udegree, int vdegree, int n);

namespace py = pybind11;
// Added to `_sprout_lpy` (lpy/api/types.cpp): PlantGL's curves in C++ (bind_curves.cpp:
// _PglNurbs, _PglPatch), QuantisedFunction's call in C (bind_quantised.cpp: _QuantisedBase),
// Point3Grid and AsymmetricHull (bind_shapes.cpp).
void definePlantGL(py::module_& m);
void defineQuantised(py::module_& m);
void definePointGrid(py::module_& m);
// The light module's z-buffer (bind_light.cpp: _ZBuffer, _mesh_bounds), added by definePlantGL.
void defineProjection(py::module_& m);

}  // namespace sprout::lpy
