#pragma once
// Sprout's Python PlantGL's curves evaluated in C++ (lpy/pgl_native.cpp): what the drawing
// asks of a curve without calling Python for each point.
#include <Python.h>

#include <array>
#include <memory>
#include <vector>

#include "core/turtle/curves.hpp"

namespace sprout::lpy {

// The C++ evaluator of one of Sprout's NURBS curves (NurbsCurve2D, NurbsCurve, BezierCurve2D,
// whose methods it evaluates as they would), and its stride; null for any other object (or
// a subclass that replaces how it is evaluated). Holds the GIL; clears any Python error.
std::shared_ptr<const curves::Nurbs> nativeNurbs(PyObject* curve, int& stride);

// A PlantGL shape given to @g as plantgl_drawing.py's _sprout_triangles makes it, in C++
// (lpy/pgl_meshes.cpp): its points in the shape's frame, triangles and segments indexing
// them. Nothing where the Python returns None (nothing drawable); Unknown where the Python
// must make it (what the C++ does not know, or reads its own way). Holds the GIL.
struct ShapeMesh {
    enum Kind { Nothing, Mesh, Unknown } kind = Nothing;
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<long, 3>> triangles;
    std::vector<std::array<long, 2>> segments;
};
ShapeMesh shapeMesh(PyObject* shape);

}  // namespace sprout::lpy
