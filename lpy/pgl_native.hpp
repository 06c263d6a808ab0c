#pragma once
// Sprout's Python PlantGL's curves evaluated in C++ (lpy/pgl_native.cpp): what the drawing
// asks of a curve without calling Python for each point.
#include <Python.h>

#include <memory>

#include "core/turtle/curves.hpp"

namespace sprout::lpy {

// The C++ evaluator of one of Sprout's NURBS curves (NurbsCurve2D, NurbsCurve, BezierCurve2D,
// whose methods it evaluates as they would), and its stride; null for any other object (or
// a subclass that replaces how it is evaluated). Holds the GIL; clears any Python error.
std::shared_ptr<const curves::Nurbs> nativeNurbs(PyObject* curve, int& stride);

}  // namespace sprout::lpy
